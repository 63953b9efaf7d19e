"""The .moos and .bhv readers and the nodes they build."""
