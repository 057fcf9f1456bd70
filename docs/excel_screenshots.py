"""Draw the screenshots of docs/excel.md: sheets rendered headless by LibreOffice.

Run from the repository root: ``.venv/bin/python docs/excel_screenshots.py``.
Needs LibreOffice (``soffice``) and ``pdftoppm`` (Debian package poppler-utils):
each sheet is printed to PDF by LibreOffice on one landscape page, the page
is rasterised by pdftoppm, trimmed and stored as a small PNG in docs/_static/.

The results are the gearbox example written with ``--formulas`` and
recalculated by LibreOffice; the live check is the same workbook after Fr and
n of the first support were doubled and the designation of the second was
changed, recalculated again (the marks of docs/excel.md, section 3).
"""
from __future__ import annotations

import subprocess
import sys
import tempfile
from pathlib import Path

import openpyxl
from PIL import Image, ImageChops

from bearingheat.io.excel.libreoffice import convert
from bearingheat.io.excel.workbook import calc_workbook

ROOT = Path(__file__).resolve().parents[1]
STATIC = ROOT / "docs" / "_static"

#: PNG name -> (workbook, sheet, print area); RESULTS and EDITED are the recalculated results workbooks
SHOTS = {
    "excel_template_supports.png": ("spreadsheets/template.xlsx", "Supports", "A1:AC6"),
    "excel_template_instructions.png": ("spreadsheets/template.xlsx", "Instructions", "A1:D30"),
    "excel_example_results.png": ("RESULTS", "Results", "A1:AB8"),
    "excel_live_check.png": ("EDITED", "Results", "A1:AB8"),
}


def _single_sheet(source: Path, sheet: str, area: str, target: Path, data_only: bool = False) -> Path:
    workbook = openpyxl.load_workbook(source, data_only=data_only)
    for name in list(workbook.sheetnames):
        if name != sheet:
            del workbook[name]
    ws = workbook[sheet]
    ws.sheet_state = "visible"
    ws.print_area = area
    ws.print_title_rows = ws.print_title_cols = None
    ws.row_breaks.brk = []
    ws.oddHeader.left.text = ws.oddHeader.right.text = ws.oddFooter.center.text = None
    ws.page_setup.orientation = "landscape"
    ws.page_setup.paperSize = ws.PAPERSIZE_A3
    ws.page_setup.fitToWidth = 1
    ws.page_setup.fitToHeight = 1
    ws.sheet_properties.pageSetUpPr.fitToPage = True
    ws.print_options.gridLines = False
    workbook.save(target)
    return target


def _trimmed_png(pdf: Path, png: Path) -> None:
    stem = pdf.with_suffix("")
    subprocess.run(["pdftoppm", "-png", "-r", "110", "-f", "1", "-l", "1", "-singlefile", str(pdf), str(stem)],
                   check=True)
    image = Image.open(f"{stem}.png").convert("RGB")
    background = Image.new("RGB", image.size, (255, 255, 255))
    box = ImageChops.difference(image, background).getbbox()
    image = image.crop((max(box[0] - 8, 0), max(box[1] - 8, 0), box[2] + 8, box[3] + 8))
    image.convert("P", palette=Image.Palette.ADAPTIVE, colors=64).save(png, optimize=True)


def _edited(live: Path, target: Path) -> Path:
    """The results workbook with Fr and n of the first support doubled and another designation in the second."""
    workbook = openpyxl.load_workbook(live)
    ws = workbook["Supports"]
    letter = {c.value: c.column_letter for c in ws[1]}
    for name in ("Fr", "n"):
        ws[f"{letter[name]}3"] = ws[f"{letter[name]}3"].value * 2
    ws[f"{letter['designation']}4"] = "NU2208-E"
    workbook.save(target)
    return target


def main() -> int:
    with tempfile.TemporaryDirectory() as folder:
        folder = Path(folder)
        live = folder / "gearbox_results.xlsx"
        calc_workbook(ROOT / "spreadsheets" / "gearbox_shaft_example.xlsx", live, formulas=True)
        edited = _edited(live, folder / "gearbox_edited.xlsx")
        recalculated = dict(zip(("RESULTS", "EDITED"), convert([live, edited], "xlsx", folder / "recalculated")))
        singles = []
        for png, (book, sheet, area) in SHOTS.items():
            source = recalculated.get(book, ROOT / book)
            singles.append(_single_sheet(source, sheet, area, folder / Path(png).with_suffix(".xlsx").name,
                                         data_only=book in recalculated))
        pdfs = convert(singles, "pdf", folder / "pdf")
        for pdf, png in zip(pdfs, SHOTS):
            _trimmed_png(pdf, STATIC / png)
            print(f"wrote {STATIC / png}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
