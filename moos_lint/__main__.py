from moos_lint.cli import run

run()
