"""docs/performance.md from `lightscatter bench` results: one module per section of the page
(page.py puts them in order), the command line in cli.py, scripts/write_report.py its entry point.
Every figure on the page is read from those results; nothing is typed in except seed 000's
published numbers (common.SEED)."""
