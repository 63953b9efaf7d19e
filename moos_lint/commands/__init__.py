"""What users run: the command line, the graph, the language server,
the output formats. The top layer.
"""
