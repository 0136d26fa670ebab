#!/usr/bin/python3
"""Writes docs/performance.md (to stdout), or one of its sections, from `lightscatter bench` results:
the entry point of the report package beside it (scripts/report; its command line: report/cli.py,
or --help)."""
import sys

from report.cli import main

if __name__ == "__main__":
    sys.exit(main())
