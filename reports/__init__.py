"""curvebench's report: plots and one HTML page from the harness's files (sweep results as
JSON lines, the scaling benchmark's JSON, reconstruction JSONs). Run `python -m reports --help`."""
