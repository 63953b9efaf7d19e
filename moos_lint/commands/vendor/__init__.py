"""Third-party files moos-lint ships unchanged (see each file's licence beside it)."""
