"""moos-lint: a static-analysis linter for MOOS and MOOS-IvP code."""

__version__ = "0.1.0"
