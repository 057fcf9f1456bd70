"""No data loss: what openpyxl cannot rewrite, and a fingerprint to prove what it kept.

openpyxl rewrites a workbook from its own object model. Cell values,
formulas, styles, defined names, data validations, conditional formats,
comments (as notes), merged cells, column widths and hyperlinks survive;
charts and images are redrawn from what openpyxl reads of them (chart
styles and colours, images in page headers and what else it does not
read are lost); drawing shapes, pivot tables, slicers, form controls,
ActiveX controls, embedded objects, threaded comments and the Excel 2010+
extensions of a sheet (``x14`` validations and formats, sparklines) are
lost, and VBA survives only with ``keep_vba``. :func:`unsupported_content` names
what such a rewrite drops, so that ``calc -o`` says what its openpyxl copy
lacks where the part-by-part edit of :mod:`bearingheat.io.excel.package`
is refused (``--in-place`` and ``write_results`` only ever use that edit).

:func:`workbook_fingerprint` reduces a workbook to comparable data (every
cell with its value and style, names, validations, comments, widths ...);
two workbooks with equal fingerprints show the same content in Excel.
"""
from __future__ import annotations

import html
import re
import zipfile

from openpyxl import load_workbook
from openpyxl.utils import get_column_letter

from bearingheat.io.excel.opc import rels_part, resolve_target, workbook_part
from bearingheat.io.excel.ownership import INPUT_MARK, RESULTS_MARK, read_marks, sheet_ref
from bearingheat.io.excel.reader import defined_name_values
from bearingheat.io.excel.record import RECORD_MARK

__all__ = ["unsupported_content", "workbook_fingerprint", "LOSSY_PARTS"]

#: package part (regular expression on the zip member name) -> what a designer calls it
LOSSY_PARTS = {
    r"^xl/charts/chart\d*\.xml$": "charts",
    r"^xl/chartsheets/": "chart sheets",
    r"^xl/media/": "images",
    r"^xl/pivotTables/": "pivot tables",
    r"^xl/pivotCache/": "pivot caches",
    r"^xl/slicers/": "slicers",
    r"^xl/timelines/": "timelines",
    r"^xl/ctrlProps/": "form controls",
    r"^xl/activeX/": "ActiveX controls",
    r"^xl/embeddings/": "embedded objects",
    r"^xl/threadedComments/": "threaded comments",
    r"^_xmlsignatures/": "digital signatures",
    r"^xl/revisions/": "change history (shared workbook)",
}
_VBA_PART = "xl/vbaProject.bin"
# openpyxl warns when it reads something it will drop; the warning names it
_WARNING_WORDS = {
    "Data Validation extension": "data validations of the Excel 2010 format (lists from other sheets)",
    "Conditional Formatting extension": "conditional formats of the Excel 2010 format",
    "Sparkline Group extension": "sparklines",
    "Slicer List extension": "slicers",
    "Unknown extension": "Excel extensions that openpyxl does not know",
}


def _drawing_shapes(archive: zipfile.ZipFile) -> bool:
    """Drawings that hold shapes or text boxes (not only charts or pictures)."""
    for name in archive.namelist():
        if re.match(r"^xl/drawings/drawing\d*\.xml$", name):
            text = archive.read(name).decode("utf-8", "replace")
            if "<xdr:sp>" in text or "<xdr:sp " in text or "<xdr:cxnSp" in text or "<xdr:grpSp" in text:
                return True
    return False


#: the objects of a VML drawing (x:ClientData ObjectType) other than notes, as a designer calls them
_VML_OBJECTS = {"Button": "form button", "Checkbox": "check box", "Radio": "option button", "Drop": "drop-down list",
                "List": "list box", "Spin": "spin button", "Scroll": "scroll bar", "Label": "label",
                "GBox": "group box", "Edit": "edit box", "Dialog": "dialog frame", "Movie": "movie",
                "Pict": "picture", "Shape": "shape", "Rect": "rectangle"}
_OBJECT_TYPE = re.compile(r'<x:ClientData\s+ObjectType="([^"]+)"(.*?)</x:ClientData>', re.DOTALL)
_ANCHOR = re.compile(r"<x:Anchor>\s*(\d+)\s*,\s*\d+\s*,\s*(\d+)")


def _vml_sheets(archive: zipfile.ZipFile) -> dict[str, str]:
    """VML drawing part -> the name of the sheet that shows it (from the workbook's and the sheets' relationships)."""
    names = set(archive.namelist())

    def targets(source: str) -> dict[str, str]:
        rels = rels_part(source)
        if rels not in names:
            return {}
        text = archive.read(rels).decode("utf-8", "replace")
        out = {}
        for element in re.findall(r"<Relationship\b[^>]*>", text):
            rid, target = re.search(r'\bId="([^"]*)"', element), re.search(r'\bTarget="([^"]*)"', element)
            if rid and target:
                out[rid.group(1)] = resolve_target(source, target.group(1))
        return out

    book = workbook_part(archive)
    if book not in names:
        return {}
    sheet_parts = targets(book)
    out = {}
    workbook = archive.read(book).decode("utf-8", "replace")
    for element in re.findall(r"<(?:\w+:)?sheet\b[^>]*>", workbook):
        name, rid = re.search(r'\bname="([^"]*)"', element), re.search(r'\br:id="([^"]*)"', element)
        part = sheet_parts.get(rid.group(1)) if rid else None
        if name and part:
            for target in targets(part).values():
                if target.endswith(".vml"):
                    out[target] = html.unescape(name.group(1))
    return out


def _vml_objects(archive: zipfile.ZipFile) -> list[str]:
    """The objects of the workbook's VML drawings other than notes (form buttons, check boxes ... of Excel's old
    kind, which openpyxl writes only with the macros), each as 'form button at Supports!P2'."""
    sheets = _vml_sheets(archive)
    found = []
    for name in archive.namelist():
        if not name.lower().endswith(".vml"):
            continue
        text = archive.read(name).decode("utf-8", "replace")
        for kind, body in _OBJECT_TYPE.findall(text):
            if kind == "Note":
                continue
            what = _VML_OBJECTS.get(kind, f"{kind} control")
            anchor = _ANCHOR.search(body)
            sheet = sheets.get(name)
            if anchor is not None and sheet is not None:
                cell = f"{get_column_letter(int(anchor.group(1)) + 1)}{int(anchor.group(2)) + 1}"
                what += f" at {sheet_ref(sheet)}!{cell}"
            elif sheet is not None:
                what += f" on sheet {sheet!r}"
            if what not in found:
                found.append(what)
    return found


def unsupported_content(path, workbook=None, *, keep_vba: bool = True) -> list[str]:
    """What rewriting ``path`` with openpyxl would drop, in words ('charts', 'images', ...); [] when nothing.

    ``workbook`` is the loaded workbook (its load warnings are checked too). Without ``keep_vba`` the
    objects of VML drawings other than notes (an old-style form button ...) are named one by one: openpyxl
    keeps a VML drawing only together with the macros.
    """
    found: list[str] = []
    with zipfile.ZipFile(path) as archive:
        names = archive.namelist()
        for pattern, what in LOSSY_PARTS.items():
            if any(re.match(pattern, n) for n in names) and what not in found:
                found.append(what)
        if _drawing_shapes(archive):
            found.append("drawing shapes and text boxes")
        if _VBA_PART in names and not keep_vba:
            found.append("VBA macros")
        if not keep_vba:
            found += [what for what in _vml_objects(archive) if what not in found]
    for message in getattr(workbook, "_bearingheat_load_warnings", ()):
        for words, what in _WARNING_WORDS.items():
            if words in message and what not in found:
                found.append(what)
    return found


def _style_key(cell) -> tuple:
    if not cell.has_style:
        return ()
    return (repr(cell.font), repr(cell.fill), repr(cell.border), repr(cell.alignment), cell.number_format,
            repr(cell.protection), cell.style)


def workbook_fingerprint(workbook_or_path, *, skip_sheets=()) -> dict:
    """Everything a designer sees in a workbook, as plain comparable data (sheets in ``skip_sheets`` left out, and
    the hidden names that mark them as bearingheat's results sheets, :mod:`.ownership`)."""
    workbook = workbook_or_path
    if not hasattr(workbook_or_path, "worksheets"):
        workbook = load_workbook(workbook_or_path, keep_vba=str(workbook_or_path).endswith(".xlsm"))
    marks = read_marks(defined_name_values(workbook))
    skipped_marks = {f"{prefix}{k}".lower() for k, (results, _) in marks.items() if results in skip_sheets
                     for prefix in (RESULTS_MARK, INPUT_MARK, RECORD_MARK)}
    out: dict = {
        "sheets": [(ws.title, ws.sheet_state) for ws in workbook.worksheets if ws.title not in skip_sheets],
        "defined_names": sorted((name, str(dn.attr_text), dn.localSheetId)
                                for name, dn in workbook.defined_names.items()
                                if name.lower() not in skipped_marks),
        "named_styles": sorted(str(s) for s in workbook.named_styles),
    }
    for ws in workbook.worksheets:
        if ws.title in skip_sheets:
            continue
        cells = {}
        for row in ws.iter_rows():
            for cell in row:
                if cell.value is None and not cell.has_style:
                    continue
                cells[cell.coordinate] = (cell.value, cell.data_type, _style_key(cell),
                                          cell.hyperlink.target if cell.hyperlink else None)
        comments = {c.coordinate: (c.comment.text, c.comment.author)
                    for row in ws.iter_rows() for c in row if c.comment is not None}
        out[ws.title] = {
            "cells": cells,
            "comments": comments,
            "merged": sorted(str(r) for r in ws.merged_cells.ranges),
            "validations": sorted((str(dv.sqref), dv.type, dv.formula1, dv.formula2, dv.allow_blank,
                                   dv.showErrorMessage, dv.error, dv.errorTitle, dv.prompt, dv.promptTitle)
                                  for dv in ws.data_validations.dataValidation),
            "conditional_formats": sorted((str(cf.sqref), repr([(r.type, r.operator, r.formula, repr(r.dxf))
                                                                for r in cf.rules]))
                                          for cf in ws.conditional_formatting),
            "columns": sorted((key, dim.width, dim.hidden, dim.style) for key, dim in ws.column_dimensions.items()
                              if dim.customWidth or dim.hidden or dim.style != "Normal"),
            "rows": sorted((key, dim.height, dim.hidden) for key, dim in ws.row_dimensions.items()
                           if dim.height is not None or dim.hidden),
            "freeze_panes": ws.freeze_panes,
            "sheet_names": sorted((name, str(dn.attr_text)) for name, dn in ws.defined_names.items()),
            "print_area": ws.print_area,
            # TableList.items() gives (name, ref text) pairs, not tables
            "tables": sorted((name, str(getattr(ref, "ref", ref))) for name, ref in ws.tables.items()),
            "protection": ws.protection.sheet,
            "tab_color": repr(ws.sheet_properties.tabColor),
        }
    return out
