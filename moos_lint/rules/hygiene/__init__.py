"""Configuration hygiene: blocks, launches, behavior files (H).

A family imports the rule kit and the layers below the rules, never another family.
"""
