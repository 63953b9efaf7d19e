from moos_lint.cli import main

raise SystemExit(main())
