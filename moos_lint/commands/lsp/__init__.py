"""The moos-lint language server (``moos-lint server``).

Only :mod:`moos_lint.commands.lsp.server` and :mod:`moos_lint.commands.lsp.features` import pygls
and lsprotocol; they are imported by the ``server`` command alone, so the rest
of moos-lint never pays for them. The other modules here are plain Python:

- :mod:`moos_lint.commands.lsp.documents`: the editor's open documents, served to the
  engine from memory, and which open document depends on which file;
- :mod:`moos_lint.commands.lsp.analysis`: linting one document in its context;
- :mod:`moos_lint.commands.lsp.catalogue`: where completion and parameter help come from.
"""
