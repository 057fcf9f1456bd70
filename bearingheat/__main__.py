import sys

from bearingheat.cli import main

sys.exit(main())
