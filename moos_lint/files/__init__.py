"""Files: reading them, their kinds and stamps, the project root, discovery,
and the shape of a finding (a message at a span of a file).

The bottom layer: imports nothing else of moos-lint.
"""
