"""The Excel bridge: read supports from a workbook, write results, live formulas, the template.

- :mod:`.reader`: :func:`read_supports` -> (DataFrame, :class:`SheetInfo`), :func:`with_units`; :mod:`.rows`:
  the rows and cells it does not take at face value (a table's totals row, '3.000' typed as text)
- :mod:`.writer`: :func:`write_results`, :func:`write_results_workbook`, :func:`atomic_save`
- :mod:`.workbook`: :func:`calc_workbook` (read -> calc -> write) -> :class:`WorkbookRun`
- :mod:`.package`: ``--in-place`` (and ``write_results`` on an existing workbook) as a surgical edit
  of the OPC package (only bearingheat's sheet is written; :mod:`.sheetxml` renders it from the
  layout of :mod:`.layout`, :mod:`.stylesheet` appends its styles, :mod:`.ownership` marks it as
  bearingheat's)
- :mod:`.sheets`: what calc writes for an input sheet: the results sheet and its companions
- :mod:`.formulas`: the live Excel formulas of ``calc --formulas``
- :mod:`.freshness`: the hidden copy of the inputs and the live check that marks stale results
- :mod:`.printing`: the printed results sheet (30 supports a page, titles) and its PDF
- :mod:`.safety`: what a rewrite would lose, and a fingerprint to prove what it kept
- :mod:`.style`, :mod:`.template`: the named cell styles and the designer's template
- :mod:`.libreoffice`: headless LibreOffice (recalculation, PDF, screenshots)
"""
from bearingheat.io.excel.reader import SheetInfo, read_supports, with_units
from bearingheat.io.excel.workbook import WorkbookRun, calc_workbook
from bearingheat.io.excel.writer import atomic_save, write_results, write_results_workbook

__all__ = ["read_supports", "SheetInfo", "with_units", "write_results", "write_results_workbook", "atomic_save",
           "calc_workbook", "WorkbookRun"]
