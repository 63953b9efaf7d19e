"""Names of processes, variables, sensors and actuators (N).

A family imports the rule kit and the layers below the rules, never another family.
"""
