"""Front ends: nsplug expansion, the .moos and .bhv readers, the C++ reader.

Imports only :mod:`moos_lint.files`.
"""
