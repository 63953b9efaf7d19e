"""An actuator command variable that is not THRUST, RUDDER or ELEVATOR based.

## What it does
Reports a MOOS variable that names an actuator command with another word
than `THRUST`, `RUDDER` or `ELEVATOR`: `DESIRED_THROTTLE`,
`DESIRED_STEERING`, `MOTOR_CMD`. A name is an actuator command when it
starts with `DESIRED_` or has a `CMD` / `COMMAND` word, and one of its words
is in the `actuator-words` option. Names are read wherever
`variable-name-case` reads them (helm flags and conditions, stock app
parameters; see `moos_lint/semantics/variables.py`).

Names built on the three standard actuators are fine, with any suffix:
MOOS-IvP's `DESIRED_THRUST_L` / `DESIRED_THRUST_R` for differential thrust,
or `DESIRED_RUDDERX` (a renamed output in `uSimMarineV22`'s
`post_des_rudder`). Helm set-points such as `DESIRED_HEADING`,
`DESIRED_SPEED` and `DESIRED_DEPTH` are not actuators and are not
reported. MOOS-IvP's own missions use only standard actuator names.


In a mission, a key of an app of the linted repository that renames a
variable the app publishes (a member with a default that the key changes in
`OnStartUp`) is checked too: `servo_var = SERVO_3_PWM` in the app's block
names the command it publishes, judged as the C++ names below.

In C++, it checks the names an app publishes with `Notify` when they are
known statically (literals, string constants, `#define` macros, a member with
a default that a configuration key may change). There a published name with
an actuator word is also a command when another word picks one actuator or
a command value (`MOTOR_LEFT`, `SERVO_2_PWM`, `PROP_PORT`, `FIN_SETPOINT`),
unless a word says it is a report (`MOTOR_TEMPERATURE`, `SERVO_CURRENT`,
`REPORTED_MOTOR_LEFT`, `CONSO_PROP`). An app that subscribes to
`DESIRED_THRUST`, `DESIRED_RUDDER` or `DESIRED_ELEVATOR` is the actuators'
driver: what it publishes (`ZBOAT_PWM`, the sentence it sends the motors) is
its own output, downstream of the convention, and is not judged.

## Why is this bad?
The MOOS Conventions (section 4.3) know three actuators: THRUST, RUDDER and
ELEVATOR; on land, thrust and rudder stand for throttle and steering angle.
The controllers (pMarinePID / pMarinePIDV22), simulators (uSimMarine) and
tools (uHelmScope, pMarineViewer) of MOOS-IvP publish and read
`DESIRED_THRUST`, `DESIRED_RUDDER` and `DESIRED_ELEVATOR`. A driver that
listens for `DESIRED_THROTTLE` never hears them, and the vehicle sits still.

## Example
```bhv
Behavior = BHV_Timer
{
  endflag = DESIRED_THROTTLE = 0
}
```

## How to fix
Use the standard name (`DESIRED_THRUST`), or rename the controller's output
with its own option (pMarinePIDV22 `output_suffix`).

## Options
- `actuator-words` (list of strings, default
  `["THROTTLE", "STEERING", "STEER", "MOTOR", "MOTORS", "PROPELLER", "PROP", "SERVO",
  "SERVOS", "ESC", "PWM", "FIN", "FINS"]`): words that name one of the three
  actuators another way (a vehicle's fins are its rudder and elevator). A
  control surface the three do not cover (an aileron that rolls a glider or
  an aircraft, a trim flap) has no conventional name, and `DESIRED_AILERON`
  is not reported; add the word to report it.
- `allow` (list of strings, default `[]`): names (shell-style globs) that are fine.
"""

from __future__ import annotations

import fnmatch

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule
from moos_lint.semantics.variables import STANDARD_ACTUATORS, bare_name, unit_variables

STANDARD = STANDARD_ACTUATORS
_COMMAND_WORDS = {"CMD", "COMMAND"}
#: words that make a name a report of an actuator, not a command to it
REPORT_WORDS = {
    "TEMP",
    "TEMPERATURE",
    "CURRENT",
    "VOLTAGE",
    "POWER",
    "STATUS",
    "STATE",
    "FAULT",
    "ERROR",
    "ERR",
    "REPORTED",
    "FEEDBACK",
    "MEASURED",
    "ACTUAL",
    "RPM",
    "COUNT",
    "HEALTH",
    "INFO",
    "CENTERS",
    "CENTER",
    "CONFIG",
    "ENABLED",
    "DEBUG",
    "CONSO",
    "CONSUMPTION",
    "ENERGY",
    "LOAD",
    "USAGE",
}
#: words that make a name with an actuator word a command to one actuator
#: (``MOTOR_LEFT``, ``SERVO_2_PWM``, ``PROP_PORT``)
COMMAND_SHAPE_WORDS = {
    "LEFT",
    "RIGHT",
    "L",
    "R",
    "PORT",
    "STBD",
    "STARBOARD",
    "FRONT",
    "REAR",
    "AFT",
    "FWD",
    "FORE",
    "VERTICAL",
    "HORIZONTAL",
    "LATERAL",
    "PWM",
    "SET",
    "SETPOINT",
    "OUT",
    "OUTPUT",
    "DEMAND",
    "REF",
    "PERCENT",
    "PCT",
}


def actuator_word(name: str, words: set[str], any_shape: bool = False) -> str | None:
    """The non-standard actuator word of a command variable name, if any.

    ``any_shape``: every name with an actuator word is a command unless a word says
    it is a report (names an app publishes in C++).
    """
    parts = [p for p in name.upper().split("_") if p]
    if not parts:
        return None
    is_command = name.upper().startswith("DESIRED_") or any(p in _COMMAND_WORDS for p in parts)
    if (
        any_shape
        and not any(p in REPORT_WORDS for p in parts)
        and any(p in COMMAND_SHAPE_WORDS or p.isdigit() for p in parts)
    ):
        is_command = True
    if not is_command or any(p.startswith(STANDARD) for p in parts):
        return None
    for p in parts:
        if p in words:
            return p
    return None


@rule(
    code="N005",
    name="actuator-name",
    severity=Severity.WARNING,
    scope=Scope.FILE,
    kinds=(Kind.MOOS, Kind.BHV, Kind.CPP),
    options={
        "actuator-words": [
            "THROTTLE",
            "STEERING",
            "STEER",
            "MOTOR",
            "PROPELLER",
            "PROP",
            "SERVO",
            "ESC",
            "MOTORS",
            "SERVOS",
            "PWM",
            "FIN",
            "FINS",
        ],
        "allow": [],
    },
)
def check(ctx):
    words = {str(w).upper() for w in ctx.options.get("actuator-words", [])}
    allow = [str(a) for a in ctx.options.get("allow", [])]
    if ctx.unit.kind is Kind.CPP:
        yield from cpp_check(ctx, words, allow)
        return
    seen = set()
    for ref in unit_variables(ctx.moos, ctx.bhv):
        bare = bare_name(ref.name)
        if not bare:
            continue
        seen.add((ref.line.lineno, bare))  # (the line of ref.span, without making it)
        word = actuator_word(bare, words)
        if word is None or any(fnmatch.fnmatchcase(ref.name, a) for a in allow):
            continue
        yield ctx.report(
            ref.span,
            f"`{ref.name}` names the actuator `{word}`: MOOS actuators are "
            "THRUST, RUDDER and ELEVATOR (`DESIRED_THRUST`, `DESIRED_RUDDER`, ...)",
            line=ref.line,
        )
    if ctx.moos is not None:
        yield from _configured(ctx, words, allow, seen)


def _configured(ctx, words, allow, seen):
    """``KEY = NAME`` lines renaming a command an app of the repository publishes."""
    from moos_lint.semantics.mission_model import configured_publications

    for c in configured_publications(ctx.run, ctx.moos):
        if (c.span.line, c.name) in seen or any(fnmatch.fnmatchcase(c.name, a) for a in allow):
            continue
        word = actuator_word(c.name, words, any_shape=True)
        if word:
            yield ctx.report(
                c.span,
                f"`{c.name}` names the actuator `{word}`: {c.says()}; MOOS actuators are "
                "THRUST, RUDDER and ELEVATOR (`DESIRED_THRUST`, `DESIRED_RUDDER`, ...)",
                line=c.line,
            )


def cpp_check(ctx, words, allow):
    """The C++ check: names the app publishes."""
    from moos_lint.rules.kit.cpp import cpp_findings
    from moos_lint.semantics.cpp_checks import actuator_name

    def word_of(name):
        if any(fnmatch.fnmatchcase(name, a) for a in allow):
            return None
        return actuator_word(name, words, any_shape=True)

    yield from cpp_findings(ctx, actuator_name, word_of=word_of)
