"""nsplug directives: includes, conditionals, macros (P).

A family imports the rule kit and the layers below the rules, never another family.
"""
