"""The names that decide where a project is and how it is set up.

Kept in a module of their own (no imports) so that the replay of an unchanged
run (:mod:`moos_lint.speed.replay`) checks the very names the settings and the
project root are found by.
"""

#: config files, searched at and above the paths linted, nearest first
CONFIG_FILES = (".moos-lint.toml", "moos-lint.toml", "pyproject.toml")
#: version-control folders: the project root of a run without a config file
VCS_MARKERS = (".git", ".hg", ".svn")
