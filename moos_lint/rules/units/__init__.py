"""Units, angles, frames and the work area (U).

A family imports the rule kit and the layers below the rules, never another family.
"""
