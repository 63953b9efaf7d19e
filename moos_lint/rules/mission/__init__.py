"""What the apps and behaviors of a mission accept and exchange (M).

A family imports the rule kit and the layers below the rules, never another family.
"""
