"""``calc --in-place`` and ``write_results`` over a corpus of varied workbooks (tests/workbook_corpus.py):
nothing else changes.

For every workbook: either refused with the file byte-identical, or every
ZIP part except those that register the results sheet (xl/workbook.xml, its
rels, [Content_Types].xml, xl/styles.xml, the results sheet's part) is
byte-identical and in the same order, the registering parts changed only by
additions, the results sheet readable by openpyxl with the results of calc
(text as text, never as a formula), and a second run replaces its own sheet
without adding anything.
"""
from __future__ import annotations

import io
import os
import zipfile

import numpy as np
import openpyxl
import pandas as pd
import pytest
from lxml import etree
from workbook_corpus import CASES, results_part

from bearingheat.errors import ExcelError, WorkbookContentError
from bearingheat.io.excel.workbook import calc_workbook
from bearingheat.io.excel.writer import write_results

pytestmark = pytest.mark.filterwarnings("ignore:.*extension is not supported:UserWarning")

REGISTERING = {"xl/workbook.xml", "xl/_rels/workbook.xml.rels", "[Content_Types].xml", "xl/styles.xml"}


def parts(path) -> dict[str, bytes]:
    with zipfile.ZipFile(path) as archive:
        return {info.filename: archive.read(info.filename) for info in archive.infolist()}


def key(element) -> tuple:
    """An element's content (tag, attributes, children) blind to prefixes and whitespace."""
    if not isinstance(element.tag, str):
        return ("#",)
    return (element.tag, tuple(sorted(element.attrib.items())), (element.text or "").strip(),
            tuple(key(c) for c in element if isinstance(c.tag, str)))


def children(data: bytes) -> list:
    return [c for c in etree.fromstring(data) if isinstance(c.tag, str)]


def assert_added_only(before: bytes, after: bytes, where: str, *, may_drop=lambda element: False) -> None:
    """Every element of ``before`` is in ``after`` with the same content and order (some may be dropped)."""
    old = [key(c) for c in children(before) if not may_drop(c)]
    new = [key(c) for c in children(after)]
    positions = [new.index(k) if k in new else -1 for k in old]
    assert -1 not in positions, (where, [o for o, p in zip(old, positions) if p < 0])
    assert positions == sorted(positions), where


def assert_workbook_xml(before: bytes, after: bytes) -> None:
    """The workbook part: sheets and defined names only added to, calcPr only gains fullCalcOnLoad."""
    old, new = etree.fromstring(before), etree.fromstring(after)
    grow = {"sheets", "definedNames", "calcPr"}
    assert_added_only(before, after, "xl/workbook.xml",
                      may_drop=lambda e: etree.QName(e).localname in grow)
    for name in ("sheets", "definedNames"):
        old_part = old.find(f"{{*}}{name}")
        if old_part is not None:
            kept = [key(c) for c in old_part
                    if not (c.get("name") or "").startswith(("_bearingheat_results_", "_bearingheat_input_",
                                                             "_bearingheat_snapshot_", "_bearingheat_duty_",
                                                             "_bearingheat_record_"))]
            assert set(kept) <= {key(c) for c in new.find(f"{{*}}{name}")}, name
    old_calc, new_calc = old.find("{*}calcPr"), new.find("{*}calcPr")
    assert new_calc.get("fullCalcOnLoad") == "1"
    if old_calc is not None:
        assert set(old_calc.attrib.items()) - {("fullCalcOnLoad", "0")} <= set(new_calc.attrib.items())


def assert_styles_appended(before: bytes, after: bytes) -> None:
    """styles.xml: every collection keeps its entries at their index; bearingheat's are appended."""
    old = {etree.QName(c).localname: c for c in children(before)}
    new = {etree.QName(c).localname: c for c in children(after)}
    for name, element in old.items():
        old_items = [key(c) for c in element if isinstance(c.tag, str)]
        new_items = [key(c) for c in new[name] if isinstance(c.tag, str)]
        assert new_items[:len(old_items)] == old_items, name


def assert_surgical(before: dict, after: dict, results: str, may_change=(), companions=()) -> None:
    """Only the registering parts, the results sheet and its companion sheets (the copy of the inputs of
    --formulas) changed; the companions and the results sheet are the only new parts."""
    allowed = REGISTERING | {results} | set(may_change) | set(companions)
    for name, data in before.items():
        if name in allowed:
            continue
        assert name in after, f"{name} was removed"
        assert after[name] == data, f"{name} changed"
    removed = set(before) - set(after)
    assert removed <= set(may_change), removed
    assert set(after) - set(before) <= {results, "xl/styles.xml", *companions}, set(after) - set(before)
    assert [n for n in after if n in before] == [n for n in before if n in after], "the order of the parts changed"
    assert_workbook_xml(before["xl/workbook.xml"], after["xl/workbook.xml"])
    for name in ("xl/_rels/workbook.xml.rels", "[Content_Types].xml"):
        assert_added_only(before[name], after[name], name,
                          may_drop=lambda e: "calcChain" in (e.get("Type", "") + e.get("PartName", "")))
    if "xl/styles.xml" in before:
        assert_styles_appended(before["xl/styles.xml"], after["xl/styles.xml"])


def assert_results_sheet(path, run, formulas: bool) -> None:
    """The results sheet as openpyxl reads it: the header, one row per support, MR as calc computed it, text as
    text."""
    workbook = openpyxl.load_workbook(path)
    ws = workbook[run.results_sheet]
    header = [c.value for c in ws[1]]
    assert header[0] == "row" and header[-2:] == ["status", "message"]
    last = 2 + len(run.result)
    # with formulas: a blank row, then the check that the input sheet has no support without results
    assert ws.max_row == last + 2 * formulas
    if formulas:
        assert [c.value for c in ws[last + 1]] == [None] * len(header)
        assert ws.cell(last + 2, 1).value.startswith("=IF(ROWS(") and ws.cell(last + 2, 2).value is None
    assert [ws.cell(r, 1).value for r in range(3, last + 1)] == run.info.rows
    status = [ws.cell(r, header.index("status") + 1).value for r in range(3, last + 1)]
    if formulas:  # the live check: calc's status while the inputs are as computed
        assert all(text.startswith("=IF(OR(") and text.endswith(f',"{state}"))') or text.endswith(f',"{state}")')
                   for text, state in zip(status, run.result["status"])), status
        assert set(run.companions) == {"snapshot"}
        assert workbook[run.companions["snapshot"]].sheet_state == "hidden"
    else:
        assert status == list(run.result["status"])
    mr = [ws.cell(r, header.index("MR") + 1) for r in range(3, last + 1)]
    for cell, expected, state in zip(mr, run.result["MR [N*mm]"], run.result["status"]):
        if formulas and state != "error":
            assert cell.data_type == "f" and cell.value.startswith("="), cell.value
        elif np.isnan(expected):
            assert cell.value is None
        else:
            assert cell.value == pytest.approx(expected, rel=1e-15)
    text_columns = [i for i, h in enumerate(header) if h in ("id", "designation", "message")
                    or (h == "status" and not formulas)]
    for row in ws.iter_rows(min_row=3, max_row=last):
        for i in text_columns:
            assert row[i].data_type != "f", (row[i].coordinate, row[i].value)
    if "id" in header:
        # openpyxl does not undo the ST_Xstring escape of inline strings ('_x005F_x0041_' is the text '_x0041_')
        ids = [ws.cell(r, header.index("id") + 1).value for r in range(3, last + 1)]
        ids = [v.replace("_x005F_", "_") if isinstance(v, str) else v for v in ids]
        assert ids == [None if v is None or v != v else str(v) for v in run.result["id"]]
    assert ws.freeze_panes == "A3"


def run(case, sheet):
    return calc_workbook(case.path, in_place=True, sheet=sheet, formulas=case.formulas)


@pytest.mark.parametrize("name", sorted(CASES))
def test_in_place_changes_only_the_results_sheet(name, tmp_path):
    case = CASES[name](tmp_path)
    folder_before = sorted(os.listdir(tmp_path))
    data_before = case.path.read_bytes()
    if case.refused:
        with pytest.raises(case.error) as exc:
            run(case, case.sheets[0])
        assert case.refused in str(exc.value), str(exc.value)
        if case.error is WorkbookContentError:
            assert str(exc.value).startswith(f"{case.path}: --in-place refused, ")
            assert "the file is unchanged" in str(exc.value)
        assert case.path.read_bytes() == data_before
        assert sorted(os.listdir(tmp_path)) == folder_before
        return
    before = parts(case.path)
    for feature in case.present:
        assert any(n.startswith(feature) for n in before), (feature, list(before))
    first = []
    notes = []
    for sheet, expected in zip(case.sheets, case.results):
        previous = parts(case.path)
        done = run(case, sheet)
        assert done.results_sheet == expected
        notes += done.notes
        after = parts(case.path)
        assert_surgical(previous, after, results_part(case.path, expected), case.may_change,
                        [results_part(case.path, name) for name in done.companions.values()])
        assert_results_sheet(case.path, done, case.formulas)
        first.append(done)
    for text in case.notes:
        assert any(text in note for note in notes), (text, notes)
    assert sorted(os.listdir(tmp_path)) == folder_before  # no temporary file left behind
    settled = parts(case.path)
    sheets = openpyxl.load_workbook(case.path).sheetnames
    for sheet, expected, earlier in zip(case.sheets, case.results, first):
        again = run(case, sheet)
        assert again.results_sheet == expected and again.notes == []
        assert list(again.result["status"]) == list(earlier.result["status"])  # formula inputs still have values
        np.testing.assert_array_equal(again.result["MR [N*mm]"], earlier.result["MR [N*mm]"])
    assert openpyxl.load_workbook(case.path).sheetnames == sheets
    final = parts(case.path)
    results = {results_part(case.path, name) for name in case.results}
    assert list(final) == list(settled)
    assert {n: d for n, d in final.items() if n not in results} == {n: d for n, d in settled.items()
                                                                    if n not in results}


def test_the_corpus_is_large_and_covers_the_features():
    assert len(CASES) >= 40
    refused = [name for name in CASES if name.startswith("refused_")]
    assert len(refused) >= 8 and len(CASES) - len(refused) >= 40


@pytest.mark.parametrize("name", sorted(CASES))
def test_a_copy_is_what_in_place_writes_into_the_workbook(name, tmp_path):
    """``-o`` is the same surgical edit written to a new file: byte for byte what --in-place makes of the
    workbook; where --in-place refuses, openpyxl writes the copy (or the workbook cannot be read at all), and
    the workbook is left as it was either way."""
    case = CASES[name](tmp_path)
    data = case.path.read_bytes()
    copy = tmp_path / f"copy{case.path.suffix}"
    try:
        done = calc_workbook(case.path, copy, sheet=case.sheets[0], formulas=case.formulas)
    except ExcelError as exc:
        assert case.refused, (name, str(exc))
        assert not copy.exists()
    else:
        assert case.refused or done.results_sheet == case.results[0]
        workbook = openpyxl.load_workbook(copy, read_only=True)  # (read only: it holds the file until closed)
        try:
            rows = workbook[done.results_sheet].max_row
        finally:
            workbook.close()
        assert rows == len(done.result) + (4 if case.formulas else 2)  # (formulas: the check below)
    assert case.path.read_bytes() == data
    if case.refused:
        return
    in_place = tmp_path / "in place" / case.path.name  # (the printed header names the workbook's file)
    in_place.parent.mkdir()
    in_place.write_bytes(data)
    calc_workbook(in_place, in_place=True, sheet=case.sheets[0], formulas=case.formulas)
    assert copy.read_bytes() == in_place.read_bytes()


#: the table write_results adds to every workbook of the corpus: text that looks like a formula stays text
TABLE = pd.DataFrame({"case": ["a", "=b"], "x [mm]": [1.0, 2.5], "n [rpm]": [1480, np.nan]})
TABLE_SHEET = "Shaft loads"


@pytest.mark.parametrize("name", sorted(CASES))
def test_write_results_changes_only_its_own_sheet(name, tmp_path):
    """write_results into an existing workbook is the same surgical edit as --in-place: a new last sheet (and
    what registers it), every other part byte for byte and in order; a second write replaces only that sheet's
    part. Where the edit cannot keep the workbook whole it is refused, naming write_results, the file unchanged."""
    case = CASES[name](tmp_path)
    folder_before = sorted(os.listdir(tmp_path))
    data_before = case.path.read_bytes()
    try:
        write_results(TABLE, case.path, sheet=TABLE_SHEET)
    except ExcelError as exc:
        # refused where --in-place is refused for the whole workbook, or where no sheet may be added
        assert case.refused or name == "openpyxl_structure_protected_after_first_run", (name, str(exc))
        if isinstance(exc, WorkbookContentError):
            assert str(exc).startswith(f"{case.path}: write_results refused, "), str(exc)
            assert str(exc).endswith("; the file is unchanged. Write the table to a new workbook instead")
        assert case.path.read_bytes() == data_before
        assert sorted(os.listdir(tmp_path)) == folder_before
        return
    assert not case.refused or "now holds" in case.refused, name  # (a chart on calc's results sheet: not this one)
    after = parts(case.path)
    table_part = results_part(case.path, TABLE_SHEET)
    assert_surgical(parts_of(data_before), after, table_part)
    workbook = openpyxl.load_workbook(case.path)
    assert workbook.sheetnames[-1] == TABLE_SHEET
    ws = workbook[TABLE_SHEET]
    assert [[c.value for c in row] for row in ws.iter_rows()] == [["case", "x", "n"], ["-", "mm", "rpm"],
                                                                    ["a", 1, 1480], ["=b", 2.5, None]]
    assert ws["A4"].data_type == "s" and ws["A4"].quotePrefix
    write_results(TABLE.iloc[::-1], case.path, sheet=TABLE_SHEET.upper())  # the same sheet, compared without case
    again = parts(case.path)
    assert list(again) == list(after)
    assert {n for n in after if again[n] != after[n]} == {table_part}
    assert openpyxl.load_workbook(case.path)[TABLE_SHEET]["A3"].value == "=b"
    assert sorted(os.listdir(tmp_path)) == folder_before


def parts_of(data: bytes) -> dict[str, bytes]:
    with zipfile.ZipFile(io.BytesIO(data)) as archive:
        return {info.filename: archive.read(info.filename) for info in archive.infolist()}
