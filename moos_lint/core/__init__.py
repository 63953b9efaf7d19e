"""One lint run: settings, the registry, the engine, suppressions applied,
fixes, baselines, the result.

Imports the rules and below; knows nothing of the result cache, the replay or
worker processes, which wrap it from :mod:`moos_lint.speed`.
"""
