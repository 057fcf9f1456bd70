"""Files, workbooks, figures and reports. No physics."""
