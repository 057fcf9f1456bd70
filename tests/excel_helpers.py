"""Workbooks the Excel tests build themselves."""
from __future__ import annotations

import hashlib
import os
import re
import zipfile
from pathlib import Path

import openpyxl
import pandas as pd
import pytest
from openpyxl.chart import BarChart, Reference
from openpyxl.comments import Comment
from openpyxl.formatting.rule import CellIsRule
from openpyxl.styles import Alignment, Border, Font, PatternFill, Side
from openpyxl.workbook.defined_name import DefinedName
from openpyxl.worksheet.datavalidation import DataValidation

from bearingheat.calc.table import calc
from bearingheat.io.excel.libreoffice import soffice

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE_CSV = ROOT / "examples" / "gearbox_shaft.csv"
EXAMPLE_XLSX = ROOT / "spreadsheets" / "gearbox_shaft_example.xlsx"
TEMPLATE_XLSX = ROOT / "spreadsheets" / "template.xlsx"

#: the gearbox supports with a header row and a units row (as a designer types them)
HEADER = ["id", "designation", "d", "D", "n", "Fr", "Fa", "nu", "lubrication", "arrangement", "C0", "Y", "Y0"]
UNITS = ["-", "-", "mm", "mm", "rpm", "kN", "kN", "mm^2/s", "-", "-", "kN", "1", "1"]


def gearbox_rows() -> list[list]:
    table = pd.read_csv(EXAMPLE_CSV)
    columns = ["id", "designation", "d [mm]", "D [mm]", "n [rpm]", "Fr [kN]", "Fa [kN]", "nu [mm^2/s]",
               "lubrication", "arrangement", "C0 [kN]", "Y", "Y0"]
    rows = []
    for _, record in table[columns].iterrows():
        rows.append([None if pd.isna(v) else (v.item() if hasattr(v, "item") else v) for v in record])
    return rows


def make_workbook(path, header=HEADER, units=UNITS, rows=None, *, sheet="Supports", title_rows=()):
    """A workbook with optional title rows, a header row, a units row (None: no units row) and data rows."""
    workbook = openpyxl.Workbook()
    ws = workbook.active
    ws.title = sheet
    for title in title_rows:
        ws.append(list(title))
    ws.append(list(header))
    if units is not None:
        ws.append(list(units))
    for row in gearbox_rows() if rows is None else rows:
        ws.append(list(row))
    workbook.save(path)
    return Path(path)


def add_zip_part(path, name: str, data: bytes = b"<x/>") -> None:
    """Add a package part that openpyxl does not read (e.g. xl/pivotTables/pivotTable1.xml)."""
    with zipfile.ZipFile(path, "a") as archive:
        archive.writestr(name, data)


def set_cached_value(path, sheet_index: int, coordinate: str, value: str) -> None:
    """Store a cached value for a formula cell, as Excel does when it saves (openpyxl writes none)."""
    member = f"xl/worksheets/sheet{sheet_index}.xml"
    with zipfile.ZipFile(path) as archive:
        parts = {i.filename: archive.read(i.filename) for i in archive.infolist()}
    text = parts[member].decode()
    text, count = re.subn(rf'(<c r="{coordinate}"[^>]*>)<f>([^<]*)</f><v\s*/?>(</v>)?',
                          rf"\g<1><f>\g<2></f><v>{value}</v>", text)
    assert count == 1, text[:500]
    parts[member] = text.encode()
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as archive:
        for name, data in parts.items():
            archive.writestr(name, data)


def csv_result() -> pd.DataFrame:
    return calc(pd.read_csv(EXAMPLE_CSV))


def digest(path) -> str:
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


def rich_workbook(path):
    """Supports plus everything a designer keeps in a workbook: sheets, formulas, styles, names, lists, notes."""
    make_workbook(path)
    workbook = openpyxl.load_workbook(path)
    ws = workbook["Supports"]
    ws["A3"].font = Font(bold=True, color="C00000")
    ws["F3"].fill = PatternFill("solid", fgColor="FFFF00")
    ws["F3"].number_format = "0.000"
    ws["B4"].comment = Comment("checked by J. Smith", "J. Smith")
    ws.column_dimensions["A"].width = 31.5
    ws.row_dimensions[5].height = 22
    lists = DataValidation(type="list", formula1='"grease,oil_mist,oil_bath,circulating_oil"', allow_blank=True)
    lists.add("I3:I100")
    ws.add_data_validation(lists)
    ws.conditional_formatting.add("F3:F8", CellIsRule(operator="greaterThan", formula=["5"],
                                                      fill=PatternFill("solid", fgColor="F4B084")))
    ws["O1"] = "drawing"
    ws["O1"].hyperlink = "https://example.org/drawing-G17.pdf"
    ws.freeze_panes = "C3"
    notes = workbook.create_sheet("Notes")
    notes["A1"] = "Gearbox G-17"
    notes["A1"].font = Font(size=16, bold=True)
    notes.merge_cells("A1:D1")
    notes["A3"] = "total radial load"
    notes["B3"] = "=SUM(Supports!F3:F8)"
    notes["B3"].border = Border(bottom=Side(style="double"))
    notes["B3"].alignment = Alignment(horizontal="right")
    notes["A4"] = "approved"
    notes["B4"] = True
    notes["A5"] = 0.1 + 0.2
    notes["A5"].comment = Comment("a float that has no short decimal", "QA")
    notes.column_dimensions["A"].width = 20
    hidden = workbook.create_sheet("Calc (hidden)")
    hidden["A1"] = "=Notes!B3*2"
    hidden.sheet_state = "hidden"
    workbook.defined_names["total_Fr"] = DefinedName("total_Fr", attr_text="Supports!$F$3:$F$8")
    notes.defined_names["approval"] = DefinedName("approval", attr_text="Notes!$B$4")
    workbook.save(path)
    return path


def chart_workbook(path):
    make_workbook(path)
    workbook = openpyxl.load_workbook(path)
    ws = workbook["Supports"]
    chart = BarChart()
    chart.add_data(Reference(ws, min_col=6, min_row=3, max_row=8))
    ws.add_chart(chart, "P2")
    workbook.save(path)
    return path


def image_workbook(path):
    from openpyxl.drawing.image import Image
    from PIL import Image as PILImage

    make_workbook(path)
    png = path.with_suffix(".png")
    PILImage.new("RGB", (4, 4), "red").save(png)
    workbook = openpyxl.load_workbook(path)
    workbook["Supports"].add_image(Image(str(png)), "P2")
    workbook.save(path)
    return path


def pivot_workbook(path):
    make_workbook(path)
    add_zip_part(path, "xl/pivotTables/pivotTable1.xml")
    add_zip_part(path, "xl/pivotCache/pivotCacheDefinition1.xml")
    return path


def control_workbook(path):
    make_workbook(path)
    add_zip_part(path, "xl/ctrlProps/ctrlProp1.xml")
    return path


def vba_workbook(path):
    make_workbook(path.with_suffix(".xlsx"))
    os.replace(path.with_suffix(".xlsx"), path)
    add_zip_part(path, "xl/vbaProject.bin", b"\xd0\xcf\x11\xe0 macro bytes")
    return path


def require_soffice():
    """Skip without LibreOffice, with the reason; under CI=true fail instead (.ci/run installs it)."""
    if soffice() is not None:
        return
    if os.environ.get("CI") == "true":
        pytest.fail("CI=true but LibreOffice (soffice) is not installed; .ci/run installs libreoffice-calc-nogui")
    pytest.skip("LibreOffice (soffice) is not installed: the live formulas cannot be recalculated "
                "(apt-get install libreoffice-calc-nogui)")
