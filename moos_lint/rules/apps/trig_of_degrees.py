"""A sine, cosine or tangent taken of an angle in degrees.

## What it does
Reports a call of C++'s `sin`, `cos` or `tan` (`std::` or not, and their
`f`/`l` forms) whose argument is known to be in degrees: a heading read by mail
(`NAV_HEADING`, `DESIRED_HEADING`) or, in a helm behavior, from the helm's
buffer (`getBufferDoubleVal("NAV_HEADING", ok)`), a contact's heading from its
node report (MOOS-IvP's `NodeRecord::getHeading()`), a value converted to degrees
(`MOOSRad2Deg`, `* 180 / M_PI`), or a sum or difference with such a term in
it, whatever the other terms are (`cos(90 - heading)`,
`sin(heading + tan(dx / dy))`: a sum with degrees in it is not radians),
unless another term is in radians (which of the two is wrong is then not
known). The value comes from moos-lint's value analysis of C++,
which follows it through locals, members, functions anywhere in the repository
and struct fields (README, "C++ apps"); the finding says why, as a chain.

Not reported: a value whose unit only its name suggests (`hdg_angle`,
`wamvHeading`): a simulator's heading may well be in radians; and a variable
read by mail that an app of the same repository publishes with a value not
known to be in degrees (a controller written for the repository's own
simulator gets what that simulator publishes; whether the simulator keeps the
conventions is for heading-in-radians to say). A mistake repeated in one
function is reported once, at its first use, with the number of others.

## Why is this bad?
C++'s trigonometric functions take radians. MOOS headings are degrees
(clockwise from north: the helm, pNodeReporter and uSimMarine all read
NAV_HEADING that way), so `sin(NAV_HEADING)` is the sine of a number 57 times
too large: a dead-reckoned position, a projected contact or a controller's
error turns in a direction that has nothing to do with the vehicle's, and
nothing fails.

## Example
```cpp
if(key == "NAV_HEADING")
  m_heading = msg.GetDouble();
...
m_x += m_speed * dt * sin(m_heading);
m_y += m_speed * dt * cos(m_heading);
```

## How to fix
```cpp
m_x += m_speed * dt * sin(m_heading * M_PI / 180);   // compass angle: x east, y north
m_y += m_speed * dt * cos(m_heading * M_PI / 180);
```
or convert the heading to the math angle once: `double theta = headingToRadians(m_heading);`
then `cos(theta)`, `sin(theta)`.

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule


@rule(
    code="C012",
    name="trig-of-degrees",
    severity=Severity.WARNING,
    scope=Scope.CPP,
    kinds=(Kind.CPP,),
)
def check(ctx):
    # the C++ model is loaded only by runs that lint C++
    from moos_lint.rules.kit.cpp import cpp_findings
    from moos_lint.semantics.cpp_checks import trig_of_degrees

    yield from cpp_findings(ctx, trig_of_degrees)
