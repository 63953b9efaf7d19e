"""The C++ of MOOS apps (C).

A family imports the rule kit and the layers below the rules, never another family.
"""
