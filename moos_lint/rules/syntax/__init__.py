"""How a .moos or .bhv file reads: blocks, braces, lines (R, B).

A family imports the rule kit and the layers below the rules, never another family.
"""
