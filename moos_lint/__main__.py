from moos_lint.commands.cli import run

run()
