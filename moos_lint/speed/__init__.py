"""The speed machinery: the result cache, the replay of a whole run's
output, worker processes. The only layer that wraps the core; the commands call it.
"""
