"""A string compared, after `tolower` or `toupper`, with a literal of the other case.

## What it does
Reports a comparison `var == "Literal"` (or `!=`) where the last change of
`var` before it, in the same function, made it lower case (`tolower`,
`MOOSToLower`, `boost::to_lower_copy`) and the literal has a capital, or made
it upper case (`toupper`, `MOOSToUpper`, `boost::to_upper_copy`) and the
literal has a lower-case letter. A conversion inside a call that keeps the
case (`stripBlankEnds(toupper(...))`) counts as well.

The usual place is an app's configuration loop:
`string param = tolower(biteStringX(line, '='));` followed by
`if(param == "TSS_FILE")`: the key is never recognised, whatever case the
mission writes it in.

Not reported: a comparison after any other assignment to the variable, or
after it is changed in place or handed to a function by reference; and an
alternative whose other side compares with the right case
(`param == "NAME" || param == "name"`); and a test whose branch holds no
statement (a template's `if(param == "foo") { // handled }`), which changes
nothing.

## Why is this bad?
The comparison is never true (or, with `!=`, always true), so the branch
never runs: a configuration key is silently ignored (and reported as
unhandled, or not at all), a mail key never handled, a mode never taken.
Nothing fails at run time.

## Example
```cpp
string param = tolower(biteStringX(line, '='));
if(param == "TSS_FILE")          // never true
  handled = processTSSFile(value);
```

## How to fix
Compare with the literal in the case the conversion gives
(`moos-lint check --fix` does it): `if(param == "tss_file")`.

## Options
None.
"""

from moos_lint.files.diagnostics import Severity
from moos_lint.rules.kit.declare import Kind, Scope, rule


@rule(
    code="C020",
    name="key-case-never-matches",
    severity=Severity.WARNING,
    scope=Scope.CPP,
    kinds=(Kind.CPP,),
    fixable=True,
)
def check(ctx):
    # the C++ model is loaded only by runs that lint C++
    from moos_lint.rules.kit.cpp import cpp_findings
    from moos_lint.semantics.cpp_checks import case_never_matches

    yield from cpp_findings(ctx, case_never_matches)
