"""What the parsed files mean: the mission model, the app catalogue,
variables, angles, geometry, the C++ apps' interfaces and the run's memos.

Imports the front ends and files.
"""
