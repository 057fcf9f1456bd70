"""``calc --in-place`` as a surgical edit of the workbook's OPC package: only bearingheat's sheets are written.

``calc -o`` writes the same edit to a new file (``target``): a copy that
keeps every part of the workbook too. :func:`write_table_in_place` is the
same edit for one table sheet
(:func:`bearingheat.io.excel.writer.write_results` on an existing workbook).

An .xlsx or .xlsm file is a ZIP package of parts (ECMA-376 Part 2, OPC; read and written by :mod:`.opc`).
:func:`write_results_in_place` adds or replaces the worksheet part of the
results sheet, and of its companions where there are any (the hidden copy
of the inputs of ``--formulas``, the duty cycle summary:
:class:`bearingheat.io.excel.sheets.CellsSheet`, :class:`~bearingheat.io.excel.sheets.TableSheet`),
and changes only what registers them:

- ``xl/workbook.xml``: their ``<sheet>`` entries, the hidden defined names
  that mark them as bearingheat's (:mod:`.ownership`), the print titles of
  the results sheet (``_xlnm.Print_Titles``, where it has none), a print area
  the designer set on it (``_xlnm.Print_Area``, set to the whole new sheet),
  the record of the cells written (:mod:`.record`: a re-run refuses to
  replace a sheet the designer has typed on since), and
  ``calcPr fullCalcOnLoad="1"`` so that Excel and LibreOffice recalculate
  formulas (the live formulas, and the designer's formulas that read the
  results) when the file is opened;
- ``xl/_rels/workbook.xml.rels`` and ``[Content_Types].xml`` for a new sheet;
- ``xl/styles.xml``: bearingheat's cell formats, number formats and the
  differential formats of its conditional formats appended
  (:mod:`.stylesheet`), nothing renumbered;
- ``xl/calcChain.xml`` only when a replaced results sheet had formulas in it.

Every other part is copied byte for byte, in the same order, so whatever the
workbook holds (charts, images, form controls, connections, custom XML,
dynamic-array metadata, printer settings, cached formula values, rich text,
notes, pivot caches, VBA ...) is kept without being understood. Text is
written as inline strings, so the shared strings are not touched.

What cannot be kept is refused with
:class:`~bearingheat.errors.WorkbookContentError` and the file left as it
was: an encrypted (password to open) or digitally signed workbook, a Strict
Open XML workbook, a write-reservation password, a shared workbook with a
change history, a workbook whose structure is protected (no sheet may be
added), and a results sheet that the designer has since given charts,
notes, tables or other parts of its own.
"""
from __future__ import annotations

import posixpath
import re
import os
from collections.abc import Callable, Collection, Sequence
from collections.abc import Set as AbstractSet
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Protocol

import pandas as pd
from lxml import etree
from openpyxl.utils import get_column_letter
from openpyxl.utils.datetime import CALENDAR_MAC_1904, CALENDAR_WINDOWS_1900

from bearingheat.errors import ExcelError, SheetContentError, WorkbookContentError
from bearingheat.io.excel.ownership import (COMPANION_MARKS, INPUT_MARK, RESULTS_MARK, TABLE_MARK,
                                            choose_companion_sheet, choose_results_sheet, mark_value,
                                            read_companions, read_marks, sheet_ref, table_mark_slots,
                                            written_sheets)
from bearingheat.io.excel import record, references
from bearingheat.io.excel.freshness import ConditionalRule
from bearingheat.io.excel.layout import split_header
from bearingheat.io.excel.opc import (MAIN, PKG_REL, CT, REL, STYLES_TYPE, WORKSHEET_TYPE, Package, parse_part,
                                      refusal, rels_part, resolve_target, write_package, xml_bytes)
from bearingheat.io.excel.printing import PrintSetup, is_bearingheat_header
from bearingheat.io.excel.sheetxml import results_sheet_xml
from bearingheat.io.excel.stylesheet import StyleSheet
from bearingheat.io.files import WorkbookLock

if TYPE_CHECKING:
    from bearingheat.io.console import Progress

__all__ = ["write_results_in_place", "write_table_in_place", "InPlaceResult"]

_M, _R, _P, _C = (f"{{{ns}}}" for ns in (MAIN, REL, PKG_REL, CT))
#: the order of the children of <workbook> (CT_Workbook)
_WORKBOOK_ORDER = ("fileVersion", "fileSharing", "workbookPr", "workbookProtection", "bookViews", "sheets",
                   "functionGroups", "externalReferences", "definedNames", "calcPr", "oleSize",
                   "customWorkbookViews", "pivotCaches", "smartTagPr", "smartTagTypes", "webPublishing",
                   "fileRecoveryPr", "webPublishObjects", "extLst")
#: elements of a replaced results sheet that are kept: its print setup and protection (CT_Worksheet order)
_KEPT_SHEET_ELEMENTS = ("sheetProtection", "printOptions", "pageMargins", "pageSetup", "headerFooter")
_KEPT_RELATIONSHIPS = {"printerSettings"}
_WHAT = {"drawing": "charts, images or shapes", "comments": "notes", "vmlDrawing": "notes or form controls",
         "table": "tables", "hyperlink": "hyperlinks", "pivotTable": "pivot tables", "threadedComment":
         "threaded comments", "control": "form controls", "oleObject": "embedded objects"}



@dataclass
class InPlaceResult:
    """What :func:`write_results_in_place` did: the results sheet, whether it replaced one, notes, the parts
    written and the companion sheets by role."""

    sheet: str
    replaced: bool
    notes: list[str]
    changed_parts: list[str]
    companions: dict[str, str] = field(default_factory=dict)


@dataclass
class _Sheet:
    name: str
    sheet_id: int
    rid: str
    part: str
    element: etree._Element


class _Workbook:
    """``xl/workbook.xml`` with its relationships, edited in memory."""

    def __init__(self, package: Package):
        self.package = package
        self.part = package.workbook
        self.root = parse_part(package.required(self.part), self.part, package.path)
        self.rels_name = rels_part(self.part)
        rels_data = package.read(self.rels_name)
        if rels_data is None:
            raise ExcelError(f"{package.path}: damaged workbook, {self.rels_name} is missing")
        self.rels = parse_part(rels_data, self.rels_name, package.path)
        self.targets = {r.get("Id"): (r.get("Type", ""), resolve_target(self.part, r.get("Target", "")))
                        for r in self.rels.iter(_P + "Relationship") if r.get("TargetMode") != "External"}
        sheets = self.root.find(_M + "sheets")
        if sheets is None:
            raise ExcelError(f"{package.path}: damaged workbook, {self.part} lists no sheets")
        self.sheets_element = sheets
        self.sheets = [_Sheet(s.get("name", ""), int(s.get("sheetId", "0")), s.get(_R + "id", ""),
                              self.targets.get(s.get(_R + "id", ""), ("", ""))[1], s)
                       for s in sheets.iter(_M + "sheet")]
        self.changed = self.rels_changed = False

    def child(self, name: str) -> etree._Element | None:
        return self.root.find(_M + name)

    def ensure_child(self, name: str) -> etree._Element:
        """The child ``name`` of <workbook>, added at its place in CT_Workbook's order when absent."""
        found = self.root.find(_M + name)
        if found is not None:
            return found
        element = etree.Element(_M + name)
        later = _WORKBOOK_ORDER[_WORKBOOK_ORDER.index(name) + 1:]
        for index, node in enumerate(self.root):
            if isinstance(node.tag, str) and etree.QName(node).localname in later:
                self.root.insert(index, element)
                break
        else:
            self.root.append(element)
        return element

    def names(self) -> list[tuple[str, str]]:
        names = self.child("definedNames")
        if names is None:
            return []
        return [(n.get("name", ""), n.text or "") for n in names.iter(_M + "definedName")
                if n.get("localSheetId") is None]

    def set_marks(self, k: int, results: str, source: str, stale: list[int],
                  companions: dict[str, str] | None = None, written: str | None = None) -> None:
        """Write the marks of pair ``k`` (results sheet, input sheet, companion sheets by role, the record of what
        the results sheet holds, :mod:`.record`); drop the marks of pairs in ``stale``."""
        names = self.ensure_child("definedNames")
        wanted = {f"{RESULTS_MARK}{k}": mark_value(results), f"{INPUT_MARK}{k}": mark_value(source)}
        wanted.update({f"{COMPANION_MARKS[role]}{k}": mark_value(sheet) for role, sheet in (companions or {}).items()})
        if written is not None:
            wanted[f"{record.RECORD_MARK}{k}"] = written
        drop = {f"{m}{j}".lower() for j in stale for m in (RESULTS_MARK, INPUT_MARK, record.RECORD_MARK)}
        for element in list(names.iter(_M + "definedName")):
            if element.get("localSheetId") is not None:
                continue
            name = element.get("name", "")
            if name.lower() in drop:
                names.remove(element)
                self.changed = True
            elif name in wanted:
                if element.text != wanted[name]:
                    element.text = wanted.pop(name)
                    self.changed = True
                else:
                    wanted.pop(name)
        for name, value in wanted.items():
            self.add_mark(name, value)

    def add_mark(self, name: str, value: str) -> None:
        """A hidden, workbook-scoped defined name (a mark of :mod:`.ownership`)."""
        element = etree.SubElement(self.ensure_child("definedNames"), _M + "definedName", {"name": name, "hidden": "1"})
        element.text = value
        self.changed = True

    def _sheet_name(self, sheet: _Sheet, name: str) -> etree._Element | None:
        """The defined name ``name`` (e.g. '_xlnm.Print_Area', in any letter case) local to ``sheet``, or None."""
        names = self.child("definedNames")
        index = str(self.sheets.index(sheet))
        for element in names.iter(_M + "definedName") if names is not None else ():
            if element.get("name", "").lower() == name.lower() and element.get("localSheetId") == index:
                return element
        return None

    def print_titles(self, sheet: _Sheet, value: str) -> None:
        """Give ``sheet`` print titles (``_xlnm.Print_Titles``) unless it has some."""
        if self._sheet_name(sheet, "_xlnm.Print_Titles") is not None:
            return
        element = etree.SubElement(self.ensure_child("definedNames"), _M + "definedName",
                                   {"name": "_xlnm.Print_Titles", "localSheetId": str(self.sheets.index(sheet))})
        element.text = value
        self.changed = True

    def extend_print_area(self, sheet: _Sheet, value: str) -> str | None:
        """Set the print area of ``sheet`` that the designer gave it (``_xlnm.Print_Area``) to ``value``, the whole
        new results sheet: one set for fewer supports would leave the new ones off the paper and the PDF. The
        note that says so; None where the sheet has no print area or it is ``value`` already."""
        element = self._sheet_name(sheet, "_xlnm.Print_Area")
        old = None if element is None else (element.text or "").strip()
        if element is None or old == value:
            return None
        element.text = value
        self.changed = True
        return (f"the print area of sheet {sheet.name!r} ({old}) now covers the results written, {value}; "
                "set it again (Page Layout > Print Area) to print less")

    def full_calc_on_load(self) -> None:
        calc = self.ensure_child("calcPr")
        if calc.get("fullCalcOnLoad") not in ("1", "true"):
            calc.set("fullCalcOnLoad", "1")
            self.changed = True

    def relationship(self, kind: str) -> tuple[str, str] | None:
        """(rId, part) of the first relationship of type ``.../kind``."""
        for rid, (rel_type, target) in self.targets.items():
            if rel_type.endswith("/" + kind):
                return rid, target
        return None

    def add_relationship(self, kind: str, part: str) -> str:
        used = {r.get("Id") for r in self.rels.iter(_P + "Relationship")}
        number = 1 + max([int(m.group(1)) for u in used if (m := re.fullmatch(r"rId(\d+)", u or ""))] + [0])
        rid = f"rId{number}"
        target = posixpath.relpath(part, posixpath.dirname(self.part) or ".")
        etree.SubElement(self.rels, _P + "Relationship", {"Id": rid, "Type": f"{REL}/{kind}", "Target": target})
        self.targets[rid] = (f"{REL}/{kind}", part)
        self.rels_changed = True
        return rid

    def remove_relationship(self, rid: str) -> None:
        for element in self.rels.iter(_P + "Relationship"):
            if element.get("Id") == rid:
                self.rels.remove(element)
                self.rels_changed = True
                return

    def add_sheet(self, name: str, part: str, hidden: bool = False) -> _Sheet:
        rid = self.add_relationship("worksheet", part)
        sheet_id = 1 + max([s.sheet_id for s in self.sheets] + [0])
        attributes = {"name": name, "sheetId": str(sheet_id)} | ({"state": "hidden"} if hidden else {})
        element = etree.SubElement(self.sheets_element, _M + "sheet", {**attributes, _R + "id": rid})
        self.changed = True
        sheet = _Sheet(name, sheet_id, rid, part, element)
        self.sheets.append(sheet)
        return sheet


class _ContentTypes:
    def __init__(self, package: Package):
        self.name = package.find("[Content_Types].xml") or "[Content_Types].xml"
        self.root = parse_part(package.required(self.name), self.name, package.path)
        self.changed = False

    def override(self, part: str, content_type: str) -> None:
        for element in self.root.iter(_C + "Override"):
            if element.get("PartName", "").lstrip("/").lower() == part.lower():
                return
        etree.SubElement(self.root, _C + "Override", {"PartName": "/" + part, "ContentType": content_type})
        self.changed = True

    def remove(self, part: str) -> None:
        for element in list(self.root.iter(_C + "Override")):
            if element.get("PartName", "").lstrip("/").lower() == part.lower():
                self.root.remove(element)
                self.changed = True


def _new_sheet_part(package: Package, workbook_part: str, reserved: Collection[str] = ()) -> str:
    folder = posixpath.join(posixpath.dirname(workbook_part), "worksheets")
    taken = {n.lower() for n in package.names()} | {n.lower() for n in reserved}
    k = 1
    while posixpath.join(folder, f"sheet{k}.xml").lower() in taken:
        k += 1
    return posixpath.join(folder, f"sheet{k}.xml")


def _element_text(element: etree._Element) -> str:
    """An element of a worksheet as text for the new worksheet part, without the declarations of the two
    namespaces that part's root declares itself (so a second run writes the same bytes)."""
    text = etree.tostring(element, encoding="unicode", with_tail=False)
    return re.sub(rf'\s+xmlns(:r)?="({re.escape(MAIN)}|{re.escape(REL)})"',
                  lambda m: m.group(0) if (m.group(1) == ":r") != (m.group(2) == REL) else "", text, count=2)


def _kept_setup(package: Package, sheet: _Sheet, whose: str) -> dict[str, str]:
    """The print setup and protection XML of a sheet of bearingheat's about to be replaced, by element name
    (and sheetPr's pageSetUpPr), without the page header bearingheat wrote (it is written anew); or a refusal
    naming what the sheet holds that the replacement would lose."""
    lost = []
    for relationship in package.relationships(sheet.part):
        kind = relationship.get("Type", "").rsplit("/", 1)[-1]
        if kind not in _KEPT_RELATIONSHIPS:
            what = _WHAT.get(kind, kind)
            if what not in lost:
                lost.append(what)
    if lost:
        why = (f"sheet {sheet.name!r} ({whose}) now holds {', '.join(lost)} that replacing it would lose; move them "
               "to another sheet or delete the sheet, then run again")
        raise SheetContentError(str(refusal(package.path, why, package.action)), why)
    data = package.read(sheet.part)
    if data is None:
        return {}
    root = parse_part(data, sheet.part, package.path)
    kept = {etree.QName(child).localname: _element_text(child)
            for child in root if isinstance(child.tag, str) and etree.QName(child).localname in _KEPT_SHEET_ELEMENTS}
    if "headerFooter" in kept and is_bearingheat_header(kept["headerFooter"]):
        del kept["headerFooter"]
    sheet_pr = root.find(_M + "sheetPr")
    setup_pr = sheet_pr.find(_M + "pageSetUpPr") if sheet_pr is not None else None
    if setup_pr is not None and setup_pr.attrib:  # an empty one says nothing (openpyxl writes one)
        kept["pageSetUpPr"] = _element_text(setup_pr)
    return kept


def _old_cells(package: Package, sheet: _Sheet, shared_part: str | None) -> record.SheetCells | None:
    """The cells of the results sheet a run wrote before (:func:`.record.read_cells`), read once for its old headers
    and its record; None where the part is missing."""
    data = package.read(sheet.part)
    if data is None:
        return None
    return record.read_cells(data, record.shared_strings(package.read(shared_part)) if shared_part else [])


def _foreign_edit(package: Package, sheet: _Sheet, cells: record.SheetCells, recorded: tuple[str, str] | None,
                  target: Path | None) -> list[str]:
    """Refuse to replace a results sheet that holds what bearingheat did not write (:mod:`.record`), naming the
    first such cell; into a copy (``target``) it is written with a note instead, as the workbook keeps the edit.
    The notes: that, or that a sheet without a record was checked outside its table only."""
    found = record.foreign_edit(cells, recorded)
    if found is None:
        return [] if recorded is not None else [
            f"sheet {sheet.name!r} has no record of the cells bearingheat wrote (an earlier version wrote it): "
            "nothing was found beyond its table, and it was replaced; edits inside the table cannot be told from "
            "bearingheat's own cells. From now on any edit of it is found"]
    where, value = found
    if value is None:
        what = (f"sheet {sheet.name!r} was edited since bearingheat wrote it: what {sheet_ref(sheet.name)}!{where} "
                "holds (a value, a formula, a conditional format, a validation, merged cells or the tab colour) "
                "differs from what bearingheat wrote")
        remedy = "move your edits to another sheet or run with -o to write a copy"
    else:
        shown = value if len(value) <= 60 else value[:57] + "..."
        what = f"{sheet_ref(sheet.name)}!{where} holds {shown!r} that bearingheat did not write"
        remedy = "move it to another sheet or run with -o to write a copy"
    if target is not None:
        return [f"{what}; the copy {target} has the results sheet without it (the workbook keeps it)"]
    raise WorkbookContentError(f"{package.path}: {what}; {remedy}; the file is unchanged")


def _drop_from_calc_chain(data: bytes, sheet_id: int, where: str, path: str | os.PathLike[str]) -> bytes | None:
    """The calc chain without the cells of sheet ``sheet_id`` (None: nothing is left; ``data``: nothing changed)."""
    root = parse_part(data, where, path)
    cells = [c for c in root if isinstance(c.tag, str) and etree.QName(c).localname == "c"]
    effective: list[int | None] = []
    current = None
    for cell in cells:
        index = cell.get("i")
        current = int(index) if index is not None else current
        effective.append(current)
    if sheet_id not in effective:
        return data
    previous = None
    for cell, sheet in zip(cells, effective):
        if sheet == sheet_id:
            root.remove(cell)
            continue
        if sheet != previous and cell.get("i") is None:
            cell.set("i", str(sheet))
        previous = sheet
    return xml_bytes(root) if any(s != sheet_id for s in effective) else None


def _drop_sheet_from_chain(package: Package, workbook: _Workbook, types: _ContentTypes, sheet: _Sheet,
                           changes: dict[str, bytes], removed: set[str]) -> None:
    """The calc chain without the formula cells of a sheet that is written anew."""
    chain = workbook.relationship("calcChain")
    if chain is None:
        return
    data = changes.get(chain[1], package.read(chain[1]))
    if data is None:
        return
    new = _drop_from_calc_chain(data, sheet.sheet_id, chain[1], package.path)
    if new is None:
        member = package.find(chain[1])
        if member is not None:
            removed.add(member)
        changes.pop(chain[1], None)
        workbook.remove_relationship(chain[0])
        types.remove(chain[1])
    elif new is not data:
        changes[chain[1]] = new


class Companion(Protocol):
    """A companion sheet of the results sheet (:class:`bearingheat.io.excel.sheets.CellsSheet`, ``TableSheet``)."""

    role: str
    base: str
    hidden: bool

    def render(self, styles: StyleSheet) -> bytes: ...


#: (column, row position) -> formula of the results sheet
CellFormulas = dict[tuple[str, int], str]


def write_results_in_place(package: Package, input_sheet: str, table: pd.DataFrame, *, lock: WorkbookLock | None,
                           target: Path | None = None, units: dict[str, str] | None = None,
                           formulas: CellFormulas | Callable[[dict[str, str]], CellFormulas] | None = None,
                           progress: Progress | None = None, placeholders: Collection[str] = (),
                           rules: Sequence[ConditionalRule] = (), print_setup: PrintSetup | None = None,
                           companions: Sequence[Companion] = (), hidden_columns: Sequence[str] = (),
                           footer: dict[str, str] | None = None) -> InPlaceResult:
    """Write ``table`` as the results sheet of ``input_sheet`` into the workbook of ``package``.

    The results sheet that bearingheat marked for ``input_sheet`` is replaced
    (at its place, under its present name); without one a new sheet is added
    at the end of the tabs (no other sheet moves, so macros that count
    sheets keep working), named ``Results`` or ``<sheet> results``, or the
    next free ``(2)`` name when a sheet of the designer's holds that name
    (then a note says so); ``placeholders`` are sheets that hold nothing of
    the designer's and may be filled although unmarked (the template's empty
    'Results' sheet, :func:`bearingheat.io.excel.template.is_placeholder`).
    ``companions`` (objects with ``role``, ``base`` name, ``hidden`` and
    ``render(styles) -> bytes``: :mod:`bearingheat.io.excel.sheets`) are
    written the same way: the sheet
    their mark names is replaced, else one is added after the last sheet.
    ``formulas`` is a dict of (column, row position) -> formula, or a
    callable that gives it from the companions' names by role (the status
    formulas name the inputs' copy). ``rules`` are conditional formats,
    ``print_setup`` a :class:`bearingheat.io.excel.printing.PrintSetup`,
    ``hidden_columns`` the results sheet's collapsed columns, ``footer`` the
    formulas of cells below its table by address.
    ``lock`` (:func:`bearingheat.io.files.workbook_lock`) is checked just
    before the file is replaced. ``target``: the edited package is written
    there instead of over the workbook (``calc -o``: a copy that keeps every
    part of the workbook as well; ``lock`` is None then). Returns an
    :class:`InPlaceResult`.
    """
    workbook = _Workbook(package)
    whose = f"bearingheat's results of {input_sheet!r}"
    marks = read_marks(workbook.names())
    owned = read_companions(workbook.names())
    present = {s.name.casefold() for s in workbook.sheets}
    name, replace, note = choose_results_sheet([s.name for s in workbook.sheets], marks, input_sheet,
                                               placeholders=placeholders)
    current = next((k for k, (results, source) in marks.items()
                    if results is not None and results.casefold() == name.casefold() and source == input_sheet), None)
    stale = [k for k, (results, _) in marks.items() if results is None or results.casefold() not in present]
    written_before = current is not None  # the sheet is bearingheat's by its mark, not the template's placeholder
    if current is None:  # a results sheet the designer deleted: its pair (and its companions) is taken again
        current = next((k for k in stale if marks[k][1] == input_sheet), None)
    k = current if current is not None else 1 + max(list(marks) + list(owned) + [0])
    chosen: dict[str, tuple[str, bool]] = {}
    for companion in companions:
        chosen[companion.role] = choose_companion_sheet(
            [s.name for s in workbook.sheets], owned.get(k, {}).get(companion.role), companion.base,
            [name, input_sheet] + [n for n, _ in chosen.values()])
    edit = _Edit(package, workbook)
    if not replace or any(not again for _, again in chosen.values()):
        edit.refuse_added_sheet()
    kept: dict[str, str] = {}
    old_headers: list[str | None] = []
    notes_before: list[str] = []
    if replace:
        sheet = next(s for s in workbook.sheets if s.name == name)
        kept = edit.rewrite(sheet, whose)
        shared = workbook.relationship("sharedStrings")
        old_cells = _old_cells(package, sheet, shared[1] if shared else None) if written_before else None
        if old_cells is not None:  # (the template's placeholder lists columns, but no run wrote them)
            old_headers = references.header_row(old_cells)
            notes_before.extend(_foreign_edit(package, sheet, old_cells, record.record_names(workbook.names()).get(k),
                                              target))
    else:
        sheet = edit.add_sheet(name)
    names = {role: sheet_name for role, (sheet_name, _) in chosen.items()}
    for companion in companions:
        companion_name, again = chosen[companion.role]
        if again:
            part = next(s for s in workbook.sheets if s.name == companion_name)
            edit.rewrite(part, whose)  # refused when the designer gave it charts, notes ...
            if companion.hidden and part.element.get("state") != "hidden":
                part.element.set("state", "hidden")
                workbook.changed = True
        else:
            part = edit.add_sheet(companion_name, hidden=companion.hidden, reserved=[sheet.part])
        edit.changes[part.part] = companion.render(edit.styles)
    cell_formulas = formulas(names) if callable(formulas) else formulas
    written_cells = record.WrittenCells()  # the record, as the cells are written (not read back)
    edit.changes[sheet.part] = results_sheet_xml(table, edit.styles.index, units=units, formulas=cell_formulas,
                                                 kept=kept, print_setup=print_setup, rules=rules,
                                                 dxf_index=edit.styles.dxf, progress=progress, title=name,
                                                 hidden_columns=hidden_columns, epoch=edit.epoch,
                                                 written=written_cells, footer=footer)
    workbook.set_marks(k, name, input_sheet, [j for j in stale if j != k], names, written_cells.record())
    if print_setup is not None:
        workbook.print_titles(sheet, print_setup.print_titles(sheet_ref(name)))
    notes = ([note] if note else []) + notes_before
    if old_headers and (moved := references.moved_columns(old_headers, [split_header(h, table[h], units)[0]
                                                                        for h in table.columns])):
        # a designer's =SUM(Results!K3:K5) reads the letter, not the quantity: say which columns moved, and who
        # reads the sheet
        every_name = [(n.get("name", ""), n.text or "") for n in workbook.root.iter(_M + "definedName")]
        readers = references.readers_of(package, name, [(s.name, s.part) for s in workbook.sheets], every_name,
                                        skip=[sheet.part, *(s.part for s in workbook.sheets if s.name in names.values())])
        notes.append(references.note(name, moved, readers))
    if replace:
        area = f"{sheet_ref(name)}!$A$1:${get_column_letter(max(len(table.columns), 1))}${len(table) + 2}"
        notes += [text] if (text := workbook.extend_print_area(sheet, area)) else []
    written = edit.write(lock, package.path if target is None else target)
    return InPlaceResult(name, replace, notes, written, names)


def write_table_in_place(package: Package, sheet: str, table: pd.DataFrame, *, lock: WorkbookLock | None,
                         units: dict[str, str] | None = None, input_columns: AbstractSet[str] = frozenset(),
                         formulas: CellFormulas | None = None) -> list[str]:
    """Write ``table`` as sheet ``sheet`` into the workbook of ``package``
    (:func:`bearingheat.io.excel.writer.write_results` on an existing workbook); the parts written.

    A sheet of that name (compared without case) is replaced at its place and
    under its own name where bearingheat wrote it (:func:`.ownership.written_sheets`),
    keeping its print setup; one the designer made is refused
    (:class:`ExcelError`), and so is a sheet of bearingheat's that the designer
    has since given charts, notes or tables (:class:`SheetContentError`).
    Otherwise the sheet is added after the last one and marked
    ``_bearingheat_table_<k>``. Every other part is kept byte for byte, as in
    :func:`write_results_in_place`; ``lock`` is checked before the file is
    replaced.
    """
    workbook = _Workbook(package)
    names = workbook.names()
    written = written_sheets(names)
    present = next((s for s in workbook.sheets if s.name.casefold() == sheet.casefold()), None)
    if present is not None and present.name.casefold() not in written:
        raise ExcelError(f"{package.path}: sheet {present.name!r} is not a sheet bearingheat wrote (it has no "
                         "bearingheat mark), so it is kept; the file is unchanged. Write the table to a sheet of "
                         "another name")
    edit = _Edit(package, workbook)
    if present is not None:
        kept = edit.rewrite(present, "a sheet bearingheat wrote")
        target = present
    else:
        edit.refuse_added_sheet()
        target, kept = edit.add_sheet(sheet), {}
        slot = 1 + max(table_mark_slots(name for name, _ in names), default=0)
        workbook.add_mark(f"{TABLE_MARK}{slot}", mark_value(target.name))
    edit.changes[target.part] = results_sheet_xml(table, edit.styles.index, units=units, formulas=formulas,
                                                  kept=kept, dxf_index=edit.styles.dxf, title=target.name,
                                                  input_columns=input_columns, tab_color=None, epoch=edit.epoch)
    return edit.write(lock, package.path)


class _Edit:
    """The parts an edit of ``package`` writes (by part name) or removes, and the workbook's styles; written out
    by :meth:`write` with every other part as it was."""

    def __init__(self, package: Package, workbook: _Workbook):
        self.package, self.workbook = package, workbook
        self.changes: dict[str, bytes] = {}
        self.removed: set[str] = set()
        self.types = _ContentTypes(package)
        self.styles_rel = workbook.relationship("styles")
        self.styles_part = (self.styles_rel[1] if self.styles_rel
                            else posixpath.join(posixpath.dirname(workbook.part), "styles.xml"))
        self.styles = StyleSheet(package.read(self.styles_part) if self.styles_rel else None)
        properties = workbook.child("workbookPr")  # the date system of date cells: 1900, or 1904 where so saved
        date1904 = properties is not None and properties.get("date1904") in ("1", "true")
        self.epoch = CALENDAR_MAC_1904 if date1904 else CALENDAR_WINDOWS_1900

    def refuse_added_sheet(self) -> None:
        """Refuse the edit when the workbook's structure is protected: no sheet may be added."""
        protection = self.workbook.child("workbookProtection")
        if protection is not None and protection.get("lockStructure") in ("1", "true"):
            raise refusal(self.package.path, "the workbook's structure is protected (Review > Protect Workbook), so "
                                             "no sheet may be added to it", self.package.action)

    def rewrite(self, sheet: _Sheet, whose: str) -> dict[str, str]:
        """Prepare a sheet of bearingheat's (``whose``: whose it is, for a refusal) to be written anew: its print
        setup and protection to keep (:func:`_kept_setup`, which refuses a sheet holding the designer's charts,
        notes ...), its formula cells out of the calc chain."""
        kept = _kept_setup(self.package, sheet, whose)
        if self.package.find(sheet.part) is None:  # a sheet entry whose part is missing: the part is written anew
            self.types.override(sheet.part, WORKSHEET_TYPE)
        _drop_sheet_from_chain(self.package, self.workbook, self.types, sheet, self.changes, self.removed)
        return kept

    def add_sheet(self, name: str, hidden: bool = False, reserved: Collection[str] = ()) -> _Sheet:
        """A new sheet after the last one, in a new worksheet part (not one of ``reserved`` or written here)."""
        part = _new_sheet_part(self.package, self.workbook.part, [*reserved, *self.changes])
        sheet = self.workbook.add_sheet(name, part, hidden=hidden)
        self.types.override(sheet.part, WORKSHEET_TYPE)
        return sheet

    def write(self, lock: WorkbookLock | None, target: Path) -> list[str]:
        """Recalculate on load, add the styles, workbook, relationships and content types that changed, and
        write the package to ``target`` (:func:`bearingheat.io.excel.opc.write_package`); the parts written."""
        workbook, changes = self.workbook, self.changes
        workbook.full_calc_on_load()
        if self.styles.changed:
            changes[self.styles_part] = self.styles.to_bytes()
            if self.styles_rel is None:
                workbook.add_relationship("styles", self.styles_part)
                self.types.override(self.styles_part, STYLES_TYPE)
        if workbook.changed:
            changes[workbook.part] = xml_bytes(workbook.root)
        if workbook.rels_changed:
            changes[workbook.rels_name] = xml_bytes(workbook.rels)
        if self.types.changed:
            changes[self.types.name] = xml_bytes(self.types.root)
        return write_package(self.package, changes, self.removed, lock, target)


