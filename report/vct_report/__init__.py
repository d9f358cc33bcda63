"""VCT Oracle report: turns run directories into a static HTML report (docs/report.md)."""
