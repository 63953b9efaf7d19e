"""moos-lint's own comments (L).

A family imports the rule kit and the layers below the rules, never another family.
"""
