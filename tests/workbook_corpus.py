"""A corpus of varied workbooks for ``calc --in-place``: what designers keep in Excel, built by the tests.

Each builder in :data:`CASES` writes one workbook into a folder (with
XlsxWriter, openpyxl, or by editing the parts of a package, as Excel,
LibreOffice and other tools leave them) and returns a :class:`Case`: the
input sheets to run, the results sheet each run must write, the parts that
show the feature is really there, or the refusal expected. The corpus test
(tests/io/excel/test_corpus.py) runs every case and checks that the file is
either unchanged (refused) or changed only in the parts that register the
results sheet.
"""
from __future__ import annotations

import re
import shutil
import struct
import zipfile
import zlib
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import openpyxl
import xlsxwriter
from excel_helpers import EXAMPLE_XLSX, HEADER, TEMPLATE_XLSX, UNITS, gearbox_rows, rich_workbook
from openpyxl.workbook.protection import WorkbookProtection

from bearingheat.errors import ExcelError, WorkbookContentError
from bearingheat.io.excel.workbook import calc_workbook

__all__ = ["Case", "CASES", "edit_package", "png_bytes"]

MAIN = "http://schemas.openxmlformats.org/spreadsheetml/2006/main"
REL = "http://schemas.openxmlformats.org/officeDocument/2006/relationships"


@dataclass
class Case:
    """One workbook of the corpus and what ``calc --in-place`` must do with it."""

    path: Path
    sheets: list = field(default_factory=lambda: [None])  # the --sheet of each run (None: the default)
    results: list = field(default_factory=lambda: ["Results"])  # the results sheet each run writes
    present: tuple = ()  # parts (or part prefixes) that carry the feature: checked before the run
    refused: str | None = None  # a refusal: text the message holds; the file must stay byte-identical
    error: type = WorkbookContentError
    may_change: tuple = ()  # further parts the edit may change or remove (the calc chain of a replaced sheet)
    notes: list = field(default_factory=list)  # texts the notes of the first round hold
    formulas: bool = False


CASES: dict[str, Callable[[Path], Case]] = {}


def case(function: Callable[[Path], Case]) -> Callable[[Path], Case]:
    CASES[function.__name__] = function
    return function


# ---- helpers --------------------------------------------------------------------------------------

def png_bytes(width: int = 4, height: int = 4) -> bytes:
    """A small red PNG."""
    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    raw = b"".join(b"\x00" + b"\xff\x00\x00" * width for _ in range(height))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def edit_package(path, replace: dict | None = None, add: dict | None = None, remove=()) -> Path:
    """Rewrite the ZIP members of a workbook: ``replace`` {name: bytes or function(bytes) -> bytes},
    ``add`` {name: bytes} (appended), ``remove`` names; every other member and the order are kept."""
    replace, add = replace or {}, add or {}
    with zipfile.ZipFile(path) as archive:
        members = [(i, archive.read(i.filename)) for i in archive.infolist()]
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as archive:
        for info, data in members:
            if info.filename in remove:
                continue
            if info.filename in replace:
                new = replace[info.filename]
                data = new(data) if callable(new) else new
            archive.writestr(info, data)
        for name, data in add.items():
            archive.writestr(name, data)
    return Path(path)


def sub(pattern: str, replacement: str, count: int = 1) -> Callable[[bytes], bytes]:
    """An edit for :func:`edit_package`: a regular-expression substitution that must match."""
    def edit(data: bytes) -> bytes:
        text, n = re.subn(pattern, replacement, data.decode("utf-8"), count=count)
        assert n, (pattern, text[:400])
        return text.encode("utf-8")
    return edit


def add_workbook_part(path, part: str, data: bytes, rel_type: str, content_type: str | None,
                      workbook_xml: Callable[[bytes], bytes] | None = None, rid: str = "rId900") -> Path:
    """A new part related from xl/workbook.xml (with its content type), as Excel writes connections and the like."""
    target = part.removeprefix("xl/")
    replace = {"xl/_rels/workbook.xml.rels": sub(
        "</Relationships>", f'<Relationship Id="{rid}" Type="{rel_type}" Target="{target}"/></Relationships>')}
    if content_type:
        replace["[Content_Types].xml"] = sub(
            "</Types>", f'<Override PartName="/{part}" ContentType="{content_type}"/></Types>')
    if workbook_xml is not None:
        replace["xl/workbook.xml"] = workbook_xml
    return edit_package(path, replace, {part: data})


def supports(ws, first_row: int = 0, rows=None, header=HEADER, units=UNITS, text_format=None) -> int:
    """The gearbox supports on an XlsxWriter sheet from ``first_row``; returns the next free row."""
    ws.write_row(first_row, 0, header)
    ws.write_row(first_row + 1, 0, units)
    for i, row in enumerate(gearbox_rows() if rows is None else rows):
        for j, value in enumerate(row):
            if value is None:
                continue
            if isinstance(value, str):
                ws.write_string(first_row + 2 + i, j, value, text_format)
            else:
                ws.write_number(first_row + 2 + i, j, value)
    return first_row + 2 + len(gearbox_rows() if rows is None else rows)


def xlsxwriter_book(path, build: Callable, sheet: str = "Supports", **options) -> Path:
    workbook = xlsxwriter.Workbook(str(path), options)
    ws = workbook.add_worksheet(sheet)
    supports(ws)
    build(workbook, ws)
    workbook.close()
    return Path(path)


def run_in_place(path, sheet=None, formulas=False):
    return calc_workbook(path, in_place=True, sheet=sheet, formulas=formulas)


def results_part(path, sheet: str) -> str:
    """The part of sheet ``sheet`` in a workbook."""
    with zipfile.ZipFile(path) as archive:
        workbook = archive.read("xl/workbook.xml").decode()
        rels = archive.read("xl/_rels/workbook.xml.rels").decode()
    name = sheet.replace("&", "&amp;").replace("'", "&apos;")
    match = re.search(rf'<sheet [^>]*name="(?:{re.escape(sheet)}|{re.escape(name)})"[^>]*r:id="([^"]+)"', workbook)
    assert match, workbook
    target = re.search(rf'Id="{match.group(1)}"[^>]*Target="([^"]+)"|Target="([^"]+)"[^>]*Id="{match.group(1)}"',
                       rels)
    return "xl/" + (target.group(1) or target.group(2)).lstrip("/").removeprefix("xl/")


# ---- XlsxWriter: what Excel features a designer adds ------------------------------------------------

@case
def plain(folder):
    return Case(xlsxwriter_book(folder / "plain.xlsx", lambda wb, ws: None))


@case
def chart_and_chart_sheet(folder):
    def build(wb, ws):
        chart = wb.add_chart({"type": "column"})
        chart.add_series({"values": "=Supports!$F$3:$F$8", "name": "Fr"})
        ws.insert_chart("P2", chart)
        sheet_chart = wb.add_chart({"type": "line"})
        sheet_chart.add_series({"values": "=Supports!$E$3:$E$8"})
        wb.add_chartsheet("Speed chart").set_chart(sheet_chart)
    return Case(xlsxwriter_book(folder / "charts.xlsx", build),
                present=("xl/charts/chart1.xml", "xl/chartsheets/sheet1.xml", "xl/drawings/drawing1.xml"))


@case
def image(folder):
    png = folder / "red.png"
    png.write_bytes(png_bytes())
    return Case(xlsxwriter_book(folder / "image.xlsx", lambda wb, ws: ws.insert_image("P2", str(png))),
                present=("xl/media/image1.png",))


@case
def form_button_and_textbox(folder):
    def build(wb, ws):
        ws.insert_button("P2", {"macro": "recalc", "caption": "Recalculate", "width": 120, "height": 30})
        ws.insert_textbox("P6", "Checked by J. Smith", {"width": 200, "height": 60})
    return Case(xlsxwriter_book(folder / "button.xlsx", build),
                present=("xl/drawings/vmlDrawing1.vml", "xl/drawings/drawing1.xml"))


@case
def notes_visible_and_sized(folder):
    def build(wb, ws):
        ws.write_comment("B3", "checked against the catalogue", {"visible": True, "x_scale": 2.5, "y_scale": 1.5,
                                                                  "author": "J. Smith", "color": "#C6EFCE"})
        ws.write_comment("F5", "load from the gear forces", {"author": "QA", "width": 300, "height": 120})
    return Case(xlsxwriter_book(folder / "notes.xlsx", build),
                present=("xl/comments1.xml", "xl/drawings/vmlDrawing1.vml"))


@case
def rich_text(folder):
    def build(wb, ws):
        bold, red = wb.add_format({"bold": True}), wb.add_format({"font_color": "red", "italic": True})
        ws.write_rich_string("A3", bold, "input shaft", " A ", red, "(locating)")
        notes = wb.add_worksheet("Notes")
        notes.write_rich_string("A1", "Gearbox ", bold, "G-17", " - ", red, "do not change")
    return Case(xlsxwriter_book(folder / "rich.xlsx", build), present=("xl/sharedStrings.xml",))


@case
def dynamic_array(folder):
    def build(wb, ws):
        other = wb.add_worksheet("Sorted")
        other.write_dynamic_array_formula("A1:A6", "=SORT(Supports!F3:F8)", None, 1.2)
        other.write_dynamic_array_formula("B1:B1", "=UNIQUE(Supports!B3:B8)", None, "6208")
    return Case(xlsxwriter_book(folder / "dynamic.xlsx", build), present=("xl/metadata.xml",))


@case
def validation_and_conditional_formats(folder):
    def build(wb, ws):
        ws.data_validation("I3:I100", {"validate": "list", "source": ["grease", "oil_mist", "oil_bath",
                                                                      "circulating_oil"]})
        ws.data_validation("F3:F100", {"validate": "decimal", "criteria": ">", "value": 0,
                                       "input_title": "Fr", "input_message": "radial load in kN"})
        ws.conditional_format("F3:F8", {"type": "cell", "criteria": ">", "value": 5,
                                        "format": wb.add_format({"bg_color": "#F4B084"})})
        ws.conditional_format("E3:E8", {"type": "data_bar", "data_bar_2010": True})
        ws.conditional_format("H3:H8", {"type": "icon_set", "icon_style": "3_arrows"})
    return Case(xlsxwriter_book(folder / "validation.xlsx", build))


@case
def validation_and_conditional_formats_with_formulas(folder):
    """The designer's own conditional formats (and their dxfs) beside the live check's."""
    case_ = validation_and_conditional_formats(folder)
    case_.formulas = True
    return case_


@case
def custom_number_formats_with_formulas(folder):
    """Number formats of the designer's (numFmt ids 164 and up) beside bearingheat's."""
    def build(wb, ws):
        ws.write_number("Z3", 1.5, wb.add_format({"num_format": "0.000"}))
        ws.write_number("Z4", 2.5, wb.add_format({"num_format": "[>=100]0;[>=10]0.0;0.00"}))
    return Case(xlsxwriter_book(folder / "formats.xlsx", build), present=("xl/styles.xml",), formulas=True)


@case
def sparklines(folder):
    return Case(xlsxwriter_book(folder / "sparklines.xlsx",
                                lambda wb, ws: ws.add_sparkline("P3", {"range": "Supports!C3:M3"})))


@case
def table_on_the_input(folder):
    def build(wb, ws):
        # a table over id, designation and d (Excel tables take no two headers that differ only in case: d, D)
        ws.add_table("A1:C8", {"name": "Supports_table", "header_row": True,
                               "columns": [{"header": h} for h in HEADER[:3]], "style": "Table Style Light 9"})
        other = wb.add_worksheet("Parts")
        other.add_table("A1:B3", {"data": [["6208", 2], ["NU208-E", 1]],
                                  "columns": [{"header": "part"}, {"header": "count"}]})
    return Case(xlsxwriter_book(folder / "table.xlsx", build), present=("xl/tables/table1.xml", "xl/tables/table2.xml"))


@case
def defined_names_and_filters(folder):
    def build(wb, ws):
        wb.define_name("total_Fr", "=SUM(Supports!$F$3:$F$8)")
        wb.define_name("Supports!local_n", "=Supports!$E$3:$E$8")
        ws.autofilter("A2:M8")
        ws.print_area("A1:M8")
        ws.repeat_rows(0, 1)
        ws.freeze_panes(2, 2)
    return Case(xlsxwriter_book(folder / "names.xlsx", build))


@case
def hidden_sheets(folder):
    def build(wb, ws):
        first = wb.add_worksheet("Hidden lists")
        first.write_column("A1", ["grease", "oil_bath"])
        first.hide()
        very = wb.add_worksheet("Very hidden")
        very.write("A1", 42)
        very.very_hidden()
        last = wb.add_worksheet("Summary")
        last.write_formula("A1", "=SUM(Supports!F3:F8)", None, 21.6)
        last.activate()
    return Case(xlsxwriter_book(folder / "hidden.xlsx", build))


@case
def protected_input_sheet(folder):
    def build(wb, ws):
        ws.protect("secret", {"format_cells": True})
        locked = wb.add_worksheet("Locked")
        locked.write("A1", "do not edit")
        locked.protect()
    return Case(xlsxwriter_book(folder / "protected.xlsx", build))


@case
def merged_title_rows(folder):
    workbook = xlsxwriter.Workbook(str(folder / "merged.xlsx"))
    ws = workbook.add_worksheet("Supports")
    ws.merge_range("A1:M1", "Gearbox G-17: supports", workbook.add_format({"bold": True, "align": "center"}))
    ws.merge_range("A2:C2", "rev. 3", None)
    supports(ws, first_row=2)
    ws.merge_range("O3:Q5", "merged note", None)
    workbook.close()
    return Case(folder / "merged.xlsx")


@case
def vba_project(folder):
    vba = folder / "vbaProject.bin"
    vba.write_bytes(b"\xd0\xcf\x11\xe0\xa1\xb1\x1a\xe1" + b"VBA project of the gearbox" * 40)

    def build(wb, ws):
        wb.add_vba_project(str(vba))
        wb.set_vba_name("ThisWorkbook")
        ws.set_vba_name("Sheet1")
        ws.insert_button("P2", {"macro": "recalc", "caption": "Run"})
    return Case(xlsxwriter_book(folder / "macros.xlsm", build), present=("xl/vbaProject.bin",))


@case
def hyperlinks_and_header_image(folder):
    png = folder / "logo.png"
    png.write_bytes(png_bytes(8, 2))

    def build(wb, ws):
        ws.write_url("O1", "https://example.org/drawing-G17.pdf", string="drawing")
        ws.write_url("O2", "internal:'Notes'!A1", string="notes")
        wb.add_worksheet("Notes").write("A1", "notes")
        ws.set_header("&L&G&RGearbox G-17", {"image_left": str(png)})
        ws.set_landscape()
        ws.set_paper(9)
    return Case(xlsxwriter_book(folder / "links.xlsx", build), present=("xl/drawings/vmlDrawing1.vml",))


@case
def custom_document_properties(folder):
    def build(wb, ws):
        wb.set_properties({"title": "Gearbox G-17", "author": "J. Smith", "company": "ACME"})
        wb.set_custom_property("Checked by", "QA")
        wb.set_custom_property("Revision", 3)
    return Case(xlsxwriter_book(folder / "properties.xlsx", build), present=("docProps/custom.xml",))


@case
def formula_inputs_with_cached_values(folder):
    workbook = xlsxwriter.Workbook(str(folder / "formulas.xlsx"))
    ws = workbook.add_worksheet("Supports")
    supports(ws)
    ws.write_formula("E4", "=E3*1", None, 1480)       # n of the second support follows the first
    ws.write_formula("F5", "=2*3.1", None, 6.2)       # a load computed in the sheet
    ws.write_formula("D6", "=80+10", None, 90)
    workbook.close()
    return Case(folder / "formulas.xlsx")


@case
def text_that_looks_like_formulas(folder):
    rows = gearbox_rows()
    rows[0][0] = '=HYPERLINK("http://evil.example","click")'
    rows[1][0] = "+shaft B"
    rows[2][0] = "@id"
    rows[3][0] = "_x0041_ literal"
    return _lookalike(folder / "lookalike.xlsx", rows)


def _lookalike(path, rows):
    workbook = xlsxwriter.Workbook(str(path), {"strings_to_formulas": False})
    ws = workbook.add_worksheet("Supports")
    supports(ws, rows=rows, text_format=workbook.add_format({"quote_prefix": True}))
    workbook.close()
    return Case(path)


@case
def stray_far_cell(folder):
    def build(wb, ws):
        ws.write("Z1048576", "stray")
        ws.write("F1048576", 1.0)  # a load far down in a contract column: one row in error, not a million
    return Case(xlsxwriter_book(folder / "stray.xlsx", build))


@case
def unicode_and_quoted_sheet_names(folder):
    return Case(xlsxwriter_book(folder / "names.xlsx", lambda wb, ws: wb.add_worksheet("Wälzlager ⚙"),
                                sheet="Q1's loads"), sheets=["Q1's loads"], results=["Q1's loads results"])


@case
def date_1904_and_constant_memory(folder):
    return Case(xlsxwriter_book(folder / "mac.xlsx", lambda wb, ws: None, date_1904=True, constant_memory=True))


# ---- names: the designer's sheets are never replaced -------------------------------------------------

@case
def user_sheet_named_results(folder):
    def build(wb, ws):
        mine = wb.add_worksheet("Results")
        mine.write("A1", "my own results, typed by hand")
        mine.write_formula("A2", "=SUM(Supports!F3:F8)", None, 21.6)
    return Case(xlsxwriter_book(folder / "mine.xlsx", build), results=["Results (2)"],
                notes=["sheet 'Results' is not a results sheet of bearingheat"])


@case
def user_sheet_named_results_lowercase(folder):
    return Case(xlsxwriter_book(folder / "lower.xlsx", lambda wb, ws: wb.add_worksheet("results").write("A1", 1)),
                results=["Results (2)"])


@case
def user_sheet_named_like_results_of_another_input(folder):
    workbook = xlsxwriter.Workbook(str(folder / "like.xlsx"))
    supports(workbook.add_worksheet("Shaft A"))
    supports(workbook.add_worksheet("Shaft B"))
    workbook.add_worksheet("Shaft B results").write("A1", "my notes on shaft B")
    workbook.close()
    return Case(folder / "like.xlsx", sheets=["Shaft A", "Shaft B"],
                results=["Shaft A results", "Shaft B results (2)"])


@case
def inputs_sharing_23_characters(folder):
    workbook = xlsxwriter.Workbook(str(folder / "shared.xlsx"))
    long_a, long_b = "Gearbox G-17 intermediate A", "Gearbox G-17 intermediate B"
    supports(workbook.add_worksheet(long_a))
    supports(workbook.add_worksheet(long_b))
    workbook.close()
    return Case(folder / "shared.xlsx", sheets=[long_a, long_b],
                results=["Gearbox G-17 intermedia results", "Gearbox G-17 interm results (2)"],
                notes=["sheet 'Gearbox G-17 intermedia results' holds the results of sheet "
                       "'Gearbox G-17 intermediate A'"])


@case
def input_named_like_its_own_results(folder):
    name = "ABCDEFGHIJKLMNOPQRSTUVW results"  # 31 characters: its results name is itself
    return Case(xlsxwriter_book(folder / "own.xlsx", lambda wb, ws: None, sheet=name), sheets=[name],
                results=["ABCDEFGHIJKLMNOPQRS results (2)"], notes=["is the input sheet"])


# ---- openpyxl and bearingheat's own workbooks ------------------------------------------------------

@case
def openpyxl_rich(folder):
    return Case(rich_workbook(folder / "rich.xlsx"))


@case
def template_placeholder(folder):
    shutil.copy(TEMPLATE_XLSX, folder / "template.xlsx")
    return Case(folder / "template.xlsx")


@case
def gearbox_example_with_formulas(folder):
    shutil.copy(EXAMPLE_XLSX, folder / "example.xlsx")
    return Case(folder / "example.xlsx", formulas=True)


@case
def openpyxl_structure_protected_after_first_run(folder):
    path = xlsxwriter_book(folder / "locked.xlsx", lambda wb, ws: None)
    run_in_place(path)
    edit_package(path, {"xl/workbook.xml": sub("<bookViews>", '<workbookProtection lockStructure="1"/><bookViews>')})
    return Case(path)


# ---- crafted parts: what other tools and Excel itself add ---------------------------------------------

@case
def data_connection(folder):
    path = xlsxwriter_book(folder / "connection.xlsx", lambda wb, ws: None)
    connections = (f'<?xml version="1.0" encoding="UTF-8" standalone="yes"?>\n<connections xmlns="{MAIN}">'
                   '<connection id="1" name="loads" type="1" refreshedVersion="6" background="1">'
                   '<dbPr connection="DSN=plant;" command="SELECT * FROM loads"/></connection></connections>')
    return Case(add_workbook_part(path, "xl/connections.xml", connections.encode(), f"{REL}/connections",
                                  "application/vnd.openxmlformats-officedocument.spreadsheetml.connections+xml"),
                present=("xl/connections.xml",))


@case
def custom_xml_parts(folder):
    path = xlsxwriter_book(folder / "customxml.xlsx", lambda wb, ws: None)
    item = b'<?xml version="1.0" encoding="UTF-8" standalone="no"?><plm xmlns="urn:acme:plm"><part>G-17</part></plm>'
    props = ('<?xml version="1.0" encoding="UTF-8" standalone="no"?><ds:datastoreItem '
             'ds:itemID="{6C0B4A35-5C5E-4C87-9F0A-1B1B2B3C4D5E}" '
             'xmlns:ds="http://schemas.openxmlformats.org/officeDocument/2006/customXml"/>').encode()
    rels = ('<?xml version="1.0" encoding="UTF-8" standalone="yes"?><Relationships xmlns="http://schemas.'
            'openxmlformats.org/package/2006/relationships"><Relationship Id="rId1" Type="http://schemas.'
            'openxmlformats.org/officeDocument/2006/relationships/customXmlProps" Target="itemProps1.xml"/>'
            '</Relationships>').encode()
    edit_package(path, {"[Content_Types].xml": sub("</Types>", '<Override PartName="/customXml/itemProps1.xml" '
                                                   'ContentType="application/vnd.openxmlformats-officedocument.'
                                                   'customXmlProperties+xml"/></Types>')},
                 {"customXml/item1.xml": item, "customXml/itemProps1.xml": props,
                  "customXml/_rels/item1.xml.rels": rels})
    return Case(_relate_custom_xml(path), present=("customXml/item1.xml", "customXml/itemProps1.xml"))


def _relate_custom_xml(path):
    return edit_package(path, {"xl/_rels/workbook.xml.rels": sub(
        "</Relationships>", f'<Relationship Id="rId901" Type="{REL}/customXml" Target="../customXml/item1.xml"/>'
                            "</Relationships>")})


@case
def printer_settings(folder):
    path = xlsxwriter_book(folder / "printer.xlsx", lambda wb, ws: ws.set_landscape())
    rels = ('<?xml version="1.0" encoding="UTF-8" standalone="yes"?>\n<Relationships xmlns="http://schemas.'
            'openxmlformats.org/package/2006/relationships"><Relationship Id="rId1" Type="'
            f'{REL}/printerSettings" Target="../printerSettings/printerSettings1.bin"/></Relationships>').encode()
    return Case(edit_package(path, {
        "xl/worksheets/sheet1.xml": sub(r'<pageSetup ', '<pageSetup r:id="rId1" '),
        "[Content_Types].xml": sub("</Types>", '<Default Extension="bin" ContentType="application/vnd.'
                                   'openxmlformats-officedocument.spreadsheetml.printerSettings"/></Types>')},
        {"xl/printerSettings/printerSettings1.bin": b"\x00DEVMODE of the plant printer\x01" * 20,
         "xl/worksheets/_rels/sheet1.xml.rels": rels}), present=("xl/printerSettings/printerSettings1.bin",))


@case
def pivot_cache_and_external_link(folder):
    path = xlsxwriter_book(folder / "pivot.xlsx", lambda wb, ws: None)
    cache = (f'<?xml version="1.0" encoding="UTF-8" standalone="yes"?>\n<pivotCacheDefinition xmlns="{MAIN}" '
             f'xmlns:r="{REL}" refreshOnLoad="1" recordCount="0"><cacheSource type="worksheet"><worksheetSource '
             'ref="A2:M8" sheet="Supports"/></cacheSource><cacheFields count="1"><cacheField name="id" numFmtId="0">'
             '<sharedItems/></cacheField></cacheFields></pivotCacheDefinition>').encode()
    link = (f'<?xml version="1.0" encoding="UTF-8" standalone="yes"?>\n<externalLink xmlns="{MAIN}">'
            '<externalBook xmlns:r="http://schemas.openxmlformats.org/officeDocument/2006/relationships" r:id="rId1">'
            '<sheetNames><sheetName val="Loads"/></sheetNames></externalBook></externalLink>').encode()
    link_rels = ('<?xml version="1.0" encoding="UTF-8" standalone="yes"?>\n<Relationships xmlns="http://schemas.'
                 'openxmlformats.org/package/2006/relationships"><Relationship Id="rId1" Type="http://schemas.'
                 'openxmlformats.org/officeDocument/2006/relationships/externalLinkPath" Target="loads.xlsx" '
                 'TargetMode="External"/></Relationships>').encode()
    add_workbook_part(path, "xl/pivotCache/pivotCacheDefinition1.xml", cache, f"{REL}/pivotCacheDefinition",
                      "application/vnd.openxmlformats-officedocument.spreadsheetml.pivotCacheDefinition+xml",
                      sub("</workbook>", '<pivotCaches><pivotCache cacheId="7" r:id="rId900"/></pivotCaches>'
                                         "</workbook>"), rid="rId900")
    add_workbook_part(path, "xl/externalLinks/externalLink1.xml", link, f"{REL}/externalLink",
                      "application/vnd.openxmlformats-officedocument.spreadsheetml.externalLink+xml",
                      sub("</sheets>", '</sheets><externalReferences><externalReference r:id="rId901"/>'
                                       "</externalReferences>"), rid="rId901")
    edit_package(path, add={"xl/externalLinks/_rels/externalLink1.xml.rels": link_rels})
    return Case(path, present=("xl/pivotCache/pivotCacheDefinition1.xml", "xl/externalLinks/externalLink1.xml"))


@case
def threaded_comments_and_persons(folder):
    path = xlsxwriter_book(folder / "threaded.xlsx", lambda wb, ws: None)
    person = (b'<?xml version="1.0" encoding="UTF-8" standalone="yes"?>\n<personList xmlns="http://schemas.'
              b'microsoft.com/office/spreadsheetml/2018/threadedcomments"><person displayName="J. Smith" '
              b'id="{00000000-0000-0000-0000-000000000001}" userId="js" providerId="None"/></personList>')
    return Case(add_workbook_part(path, "xl/persons/person.xml", person,
                                  "http://schemas.microsoft.com/office/2017/10/relationships/person",
                                  "application/vnd.ms-excel.person+xml"), present=("xl/persons/person.xml",))


@case
def excel_alternate_content_and_revision_ids(folder):
    path = xlsxwriter_book(folder / "excel365.xlsx", lambda wb, ws: None)
    return Case(edit_package(path, {"xl/workbook.xml": _excel365_workbook_xml}))


def _excel365_workbook_xml(data: bytes) -> bytes:
    text = data.decode()
    text = text.replace(f'<workbook xmlns="{MAIN}" xmlns:r="{REL}">',
                        f'<workbook xmlns="{MAIN}" xmlns:r="{REL}" '
                        'xmlns:mc="http://schemas.openxmlformats.org/markup-compatibility/2006" mc:Ignorable="x15 xr" '
                        'xmlns:x15="http://schemas.microsoft.com/office/spreadsheetml/2010/11/main" '
                        'xmlns:xr="http://schemas.microsoft.com/office/spreadsheetml/2014/revision">', 1)
    text = text.replace("<bookViews>", '<mc:AlternateContent><mc:Choice Requires="x15"><x15ac:absPath '
                        'xmlns:x15ac="http://schemas.microsoft.com/office/spreadsheetml/2010/11/ac" '
                        'url="C:\\plant\\gearbox\\"/></mc:Choice></mc:AlternateContent>'
                        '<xr:revisionPtr revIDLastSave="0" documentId="8_{1}" xr6:coauthVersionLast="47" '
                        'xmlns:xr6="http://schemas.microsoft.com/office/spreadsheetml/2016/revision6"/><bookViews>', 1)
    assert "absPath" in text and "mc:Ignorable" in text
    return text.encode()


@case
def absolute_relationship_targets(folder):
    path = xlsxwriter_book(folder / "absolute.xlsx", lambda wb, ws: wb.add_worksheet("Notes"))
    return Case(edit_package(path, {"xl/_rels/workbook.xml.rels": sub('Target="worksheets/', 'Target="/xl/worksheets/',
                                                                      count=0)}))


@case
def sheet_parts_with_a_gap(folder):
    path = xlsxwriter_book(folder / "gap.xlsx", lambda wb, ws: wb.add_worksheet("Notes").write("A1", "keep"))
    return Case(edit_package(path, {
        "xl/_rels/workbook.xml.rels": sub("worksheets/sheet2.xml", "worksheets/sheet7.xml"),
        "[Content_Types].xml": sub("/xl/worksheets/sheet2.xml", "/xl/worksheets/sheet7.xml")},
        add={"xl/worksheets/sheet7.xml": zipfile.ZipFile(path).read("xl/worksheets/sheet2.xml")},
        remove={"xl/worksheets/sheet2.xml"}))


@case
def no_styles_part(folder):
    path = xlsxwriter_book(folder / "nostyles.xlsx", lambda wb, ws: None)
    return Case(edit_package(path, {
        "xl/_rels/workbook.xml.rels": sub(r'<Relationship Id="rId\d+" Type="[^"]*/styles" Target="styles.xml"/>', ""),
        "[Content_Types].xml": sub(r'<Override PartName="/xl/styles.xml"[^>]*/>', ""),
        "xl/worksheets/sheet1.xml": lambda data: re.sub(rb' s="\d+"', b"", data)}, remove={"xl/styles.xml"}))


# ---- the results sheet after the designer worked on it --------------------------------------------

@case
def results_sheet_renamed_and_moved(folder):
    path = xlsxwriter_book(folder / "renamed.xlsx", lambda wb, ws: None)
    run_in_place(path)
    edit_package(path, {"xl/workbook.xml": _rename_results})
    return Case(path, results=["Loss 2024"])


def _rename_results(data: bytes) -> bytes:
    text = data.decode()
    text, n = re.subn(r'name="Results"', 'name="Loss 2024"', text)
    text, m = re.subn(r"Results!\$1:\$1048576", "'Loss 2024'!$1:$1048576", text)
    assert n == 1 and m == 1, text
    return text.encode()


@case
def results_sheet_deleted_by_the_designer(folder):
    path = xlsxwriter_book(folder / "deleted.xlsx", lambda wb, ws: None)
    run_in_place(path)
    part = results_part(path, "Results")
    edit_package(path, {"xl/workbook.xml": lambda d: re.sub(
        rb"Results!\$1", b"#REF!$1", re.sub(rb'<sheet name="Results"[^>]*/>', b"", d)),
        "[Content_Types].xml": sub(rf'<Override PartName="/{part}"[^>]*/>', "")}, remove={part})
    return Case(path)


@case
def copy_of_the_inputs_deleted_by_the_designer(folder):
    """The hidden copy of the inputs unhidden and deleted: the next --formulas run writes a new one."""
    path = xlsxwriter_book(folder / "copy_deleted.xlsx", lambda wb, ws: None)
    run_in_place(path, formulas=True)
    part = results_part(path, "Calc inputs")
    edit_package(path, {"xl/workbook.xml": lambda d: re.sub(
        rb"'Calc inputs'!\$1", b"#REF!$1", re.sub(rb'<sheet [^>]*name="Calc inputs"[^>]*/>', b"", d)),
        "[Content_Types].xml": sub(rf'<Override PartName="/{part}"[^>]*/>', "")}, remove={part})
    return Case(path, formulas=True)


@case
def results_sheet_with_print_setup(folder):
    path = xlsxwriter_book(folder / "print.xlsx", lambda wb, ws: None)
    run_in_place(path)
    part = results_part(path, "Results")
    rels = ('<?xml version="1.0" encoding="UTF-8" standalone="yes"?>\n<Relationships xmlns="http://schemas.'
            'openxmlformats.org/package/2006/relationships"><Relationship Id="rId1" Type="'
            f'{REL}/printerSettings" Target="../printerSettings/printerSettings9.bin"/></Relationships>').encode()
    # the designer's print setup instead of bearingheat's (margins, page setup with printer settings, header)
    edit_package(path, {part: sub("<pageMargins.*</headerFooter>", '<pageMargins left="0.2" right="0.2" top="0.5" '
                                  'bottom="0.5" header="0.1" footer="0.1"/><pageSetup paperSize="9" '
                                  'orientation="portrait" r:id="rId1"/><headerFooter><oddHeader>&amp;CLosses'
                                  '</oddHeader></headerFooter>'),
                        "[Content_Types].xml": sub("</Types>", '<Default Extension="bin" ContentType="application/'
                                                   'vnd.openxmlformats-officedocument.spreadsheetml.printerSettings"/>'
                                                   "</Types>")},
                 {"xl/printerSettings/printerSettings9.bin": b"DEVMODE" * 30,
                  part.replace("worksheets/", "worksheets/_rels/") + ".rels": rels})
    return Case(path, present=("xl/printerSettings/printerSettings9.bin",))


@case
def results_sheet_with_formulas_in_the_calc_chain(folder):
    path = xlsxwriter_book(folder / "chain.xlsx", lambda wb, ws: wb.add_worksheet("Sum").write_formula(
        "A1", "=SUM(Supports!F3:F8)", None, 21.6))
    run_in_place(path, formulas=True)
    chain = (f'<?xml version="1.0" encoding="UTF-8" standalone="yes"?>\n<calcChain xmlns="{MAIN}">'
             '<c r="M3" i="3" l="1"/><c r="M4"/><c r="A1" i="2"/><c r="N3" i="3"/></calcChain>').encode()
    add_workbook_part(path, "xl/calcChain.xml", chain, f"{REL}/calcChain",
                      "application/vnd.openxmlformats-officedocument.spreadsheetml.calcChain+xml")
    return Case(path, may_change=("xl/calcChain.xml",), present=("xl/calcChain.xml",))


# ---- refused, the file unchanged ---------------------------------------------------------------------

@case
def refused_results_sheet_with_a_chart(folder):
    path = xlsxwriter_book(folder / "chart_on_results.xlsx", lambda wb, ws: None)
    run_in_place(path)
    part = results_part(path, "Results")
    rels = ('<?xml version="1.0" encoding="UTF-8" standalone="yes"?>\n<Relationships xmlns="http://schemas.'
            'openxmlformats.org/package/2006/relationships"><Relationship Id="rId1" Type="'
            f'{REL}/drawing" Target="../drawings/drawing5.xml"/></Relationships>').encode()
    edit_package(path, add={part.replace("worksheets/", "worksheets/_rels/") + ".rels": rels,
                            "xl/drawings/drawing5.xml": b'<xdr:wsDr xmlns:xdr="http://schemas.openxmlformats.org/'
                                                        b'drawingml/2006/spreadsheetDrawing"/>'})
    return Case(path, refused="sheet 'Results' (bearingheat's results of 'Supports') now holds charts, images or "
                              "shapes that replacing it would lose")


@case
def refused_encrypted(folder):
    path = folder / "encrypted.xlsx"
    path.write_bytes(b"\xd0\xcf\x11\xe0\xa1\xb1\x1a\xe1" + b"\x00" * 500 + "EncryptionInfo".encode("utf-16-le")
                     + b"\x00" * 500)
    return Case(path, refused="the workbook is encrypted (it has a password to open)")


@case
def refused_strict_open_xml(folder):
    path = xlsxwriter_book(folder / "strict.xlsx", lambda wb, ws: None)
    return Case(edit_package(path, {"_rels/.rels": sub(
        "http://schemas.openxmlformats.org/officeDocument/2006/relationships/officeDocument",
        "http://purl.oclc.org/ooxml/officeDocument/relationships/officeDocument")}),
        refused="the workbook is saved as Strict Open XML")


@case
def refused_digitally_signed(folder):
    path = xlsxwriter_book(folder / "signed.xlsx", lambda wb, ws: None)
    return Case(edit_package(path, add={"_xmlsignatures/sig1.xml": b"<Signature/>",
                                        "_xmlsignatures/origin.sigs": b""}),
                refused="the workbook is digitally signed")


@case
def refused_shared_workbook_with_history(folder):
    path = xlsxwriter_book(folder / "shared.xlsx", lambda wb, ws: None)
    return Case(edit_package(path, add={"xl/revisions/revisionHeaders.xml": b"<headers/>"}),
                refused="shared workbook with a change history")


@case
def refused_password_to_modify(folder):
    path = xlsxwriter_book(folder / "reserved.xlsx", lambda wb, ws: None)
    return Case(edit_package(path, {"xl/workbook.xml": sub("<workbookPr", '<fileSharing userName="J. Smith" '
                                                           'reservationPassword="CBEB"/><workbookPr')}),
                refused="has a password to modify")


@case
def refused_structure_protected(folder):
    workbook = openpyxl.Workbook()
    ws = workbook.active
    ws.title = "Supports"
    ws.append(HEADER)
    ws.append(UNITS)
    for row in gearbox_rows():
        ws.append(row)
    workbook.security = WorkbookProtection(lockStructure=True)
    workbook.save(folder / "structure.xlsx")
    return Case(folder / "structure.xlsx", refused="the workbook's structure is protected")


@case
def refused_not_a_workbook(folder):
    path = folder / "renamed.xlsx"
    path.write_text("id,designation\n1,6208\n")
    return Case(path, refused="not a readable Excel workbook", error=ExcelError)


@case
def refused_damaged_part(folder):
    path = xlsxwriter_book(folder / "damaged.xlsx", lambda wb, ws: None)
    return Case(edit_package(path, {"xl/workbook.xml": b"<workbook><sheets"}), refused="damaged workbook",
                error=ExcelError)
