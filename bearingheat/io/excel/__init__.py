"""The Excel bridge: read supports from a workbook, write results, live formulas, the template."""
