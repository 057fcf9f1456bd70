"""Workbooks the Excel tests build themselves."""
from __future__ import annotations

import re
import zipfile
from pathlib import Path

import openpyxl
import pandas as pd

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
