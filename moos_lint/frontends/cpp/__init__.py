"""C++ analysis: each MOOS app's interface (what it publishes, subscribes to and reads).

The modules here are imported only when a C++ file is linted; tree-sitter and
libclang are imported lazily inside them.
"""
