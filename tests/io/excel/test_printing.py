"""The printed results: one landscape page per 30 supports, repeated headings, title, number formats, --pdf."""
from __future__ import annotations

import datetime
import re
import shutil
import subprocess
import zipfile

import openpyxl
import pytest
from excel_helpers import EXAMPLE_CSV, EXAMPLE_XLSX, gearbox_rows, make_workbook, require_soffice
from workbook_corpus import CASES, edit_package, results_part

from bearingheat.cli import main
from bearingheat.io.excel import style as st
from bearingheat.io.excel.libreoffice import convert
from bearingheat.io.excel.printing import SUPPORTS_PER_PAGE, PrintSetup, export_pdf, package_version, \
    pdf_page_count
from bearingheat.io.excel.workbook import calc_workbook

def stamps_since(start: str) -> set[str]:
    """The 'bearingheat VERSION, DATE' stamps a header written since the day ``start`` may carry: a run may cross
    midnight."""
    return {f"bearingheat {package_version()}, {day}" for day in (start, datetime.date.today().isoformat())}


def today() -> str:
    return datetime.date.today().isoformat()


def many_supports(path, n_rows: int):
    rows = gearbox_rows()
    return make_workbook(path, rows=[[f"support {i + 1}"] + rows[i % len(rows)][1:] for i in range(n_rows)])


def landscape_a4_pages(pdf) -> list[tuple[float, float]]:
    boxes = re.findall(rb"/MediaBox\s*\[\s*0\s+0\s+([\d.]+)\s+([\d.]+)\s*\]", pdf.read_bytes())
    return [(float(w), float(h)) for w, h in boxes]


def test_print_setup_of_65_supports():
    setup = PrintSetup.of("gearbox.xlsx", "Shaft 2", supports=65, title_columns=3, version="9.9", date="2030-01-02")
    assert (setup.pages, setup.breaks) == (3, [32, 62])  # rows 3-32, 33-62, 63-67
    assert setup.print_titles("'Shaft 2 results'") == "'Shaft 2 results'!$A:$C,'Shaft 2 results'!$1:$2"
    assert setup.header == '&L&"-,Bold"results of gearbox.xlsx, sheet Shaft 2&Rbearingheat 9.9, 2030-01-02'
    assert PrintSetup.of("a.csv", "", supports=30, title_columns=1).pages == 1
    assert PrintSetup.of("a.csv", "", supports=31, title_columns=1).breaks == [32]


@pytest.mark.parametrize("in_place", [False, True])
def test_results_sheet_print_setup(tmp_path, in_place):
    start = today()
    source = many_supports(tmp_path / "gearbox & co.xlsx", 65)
    if in_place:
        run = calc_workbook(source, in_place=True, formulas=True)
    else:
        run = calc_workbook(source, tmp_path / "out.xlsx")
    ws = openpyxl.load_workbook(run.output)["Results"]
    assert ws.page_setup.orientation == "landscape" and int(ws.page_setup.paperSize) == 9
    assert (ws.page_setup.fitToWidth, ws.page_setup.fitToHeight) == (1, 0)  # one page wide, breaks set the height
    assert ws.sheet_properties.pageSetUpPr.fitToPage
    assert [b.id for b in ws.row_breaks.brk] == [32, 62]
    assert ws.print_title_rows == "$1:$2" and ws.print_title_cols == "$A:$C"
    assert ws.oddHeader.left.text == "results of gearbox && co.xlsx, sheet Supports"  # '&&' prints '&'
    assert ws.oddHeader.left.font == "-,Bold"
    assert ws.oddHeader.right.text in stamps_since(start)
    assert ws.oddFooter.center.text == "page &P of &N"


def test_number_formats(tmp_path):
    run = calc_workbook(EXAMPLE_XLSX, tmp_path / "out.xlsx")
    ws = openpyxl.load_workbook(run.output)["Results"]
    header = [c.value for c in ws[1]]
    formats = {name: ws.cell(3, header.index(name) + 1).number_format for name in header}
    assert formats["MR"] == formats["M0"] == formats["NR"] == formats["Q_S"] == st.THREE_DIGITS
    assert formats["n_thr"] == formats["n_per"] == formats["P1"] == "0"
    assert formats["T_op"] == formats["nu_op"] == "0.0"
    assert formats["f0"] == formats["f1"] == "General"


@pytest.mark.integration
def test_numbers_as_shown(tmp_path):
    """LibreOffice's CSV export writes the cells as shown: rpm as integers, torques to three digits."""
    require_soffice()
    run = calc_workbook(EXAMPLE_XLSX, tmp_path / "out.xlsx")
    workbook = openpyxl.load_workbook(run.output)
    for name in workbook.sheetnames:
        if name != "Results":
            del workbook[name]
    workbook.save(tmp_path / "results.xlsx")
    as_shown = "csv:Text - txt - csv (StarCalc):44,34,76,1,,0,false,true,true"  # the 9th token: as shown
    text = convert([tmp_path / "results.xlsx"], as_shown, tmp_path / "csv")[0].read_text()
    rows = [line.split(",") for line in text.splitlines()]
    shown = dict(zip(rows[0], rows[2]))  # the 6208: MR 138.478 N*mm, NR 21.46 W, n_per 4790.25 1/min
    assert (shown["MR"], shown["NR"], shown["M2"], shown["n_per"], shown["T_op"]) == ("138", "21.5", "0.00",
                                                                                       "4790", "29.9")
    assert dict(zip(rows[0], rows[4]))["NR"] == "7.11"  # the 30208-A


@pytest.mark.integration
@pytest.mark.parametrize("n_rows, pages", [(6, 1), (65, 3)])
def test_pdf_has_one_landscape_page_per_30_supports(tmp_path, n_rows, pages):
    require_soffice()
    start = today()
    source = many_supports(tmp_path / "supports.xlsx", n_rows)
    run = calc_workbook(source, tmp_path / "out.xlsx", formulas=True)
    pdf = export_pdf(run.output, "Results", tmp_path / "out.pdf")
    assert pdf_page_count(pdf) == pages == -(-n_rows // SUPPORTS_PER_PAGE)
    assert set(landscape_a4_pages(pdf)) == {(841.89, 595.304)} or all(w > h for w, h in landscape_a4_pages(pdf))
    if shutil.which("pdftotext"):  # poppler-utils
        text = subprocess.run(["pdftotext", "-layout", str(pdf), "-"], capture_output=True, text=True).stdout
        assert text.count("results of supports.xlsx, sheet Supports") == pages
        assert max(text.count(stamp) for stamp in stamps_since(start)) == pages
        assert text.count("designation") == pages  # the header row on every page
        assert f"page {pages} of {pages}" in text


@pytest.mark.integration
def test_cli_pdf(tmp_path, capsys):
    require_soffice()
    source = many_supports(tmp_path / "in.xlsx", 35)
    out = tmp_path / "out.xlsx"
    assert main(["calc", str(source), "-o", str(out), "--pdf", "-q"]) == 0
    assert pdf_page_count(tmp_path / "out.pdf") == 2
    assert main(["calc", str(source), "-o", str(out), "--pdf", "-q"]) == 2
    assert capsys.readouterr().err == f"bearingheat calc: error: {out} exists; give --force to replace it\n"
    (tmp_path / "out.xlsx").unlink()
    assert main(["calc", str(source), "-o", str(out), "--pdf", "-q"]) == 2
    assert capsys.readouterr().err == (f"bearingheat calc: error: {tmp_path / 'out.pdf'} exists; give --force to "
                                       "replace it\n")
    assert not out.exists()  # refused before any work
    assert main(["calc", str(source), "--in-place", "--pdf", "-q"]) == 0
    assert pdf_page_count(tmp_path / "in.pdf") == 2
    csv_out = tmp_path / "from_csv.xlsx"
    assert main(["calc", str(EXAMPLE_CSV), "-o", str(csv_out), "--pdf", "-q"]) == 0
    assert pdf_page_count(tmp_path / "from_csv.pdf") == 1


def test_cli_pdf_refusals(tmp_path, capsys, monkeypatch):
    source = make_workbook(tmp_path / "in.xlsx")
    assert main(["calc", str(source), "-o", str(tmp_path / "out.csv"), "--pdf"]) == 2
    assert capsys.readouterr().err == ("bearingheat calc: error: --pdf prints the results sheet of a workbook: give "
                                       "-o OUTPUT.xlsx (or --in-place)\n")
    monkeypatch.setenv("PATH", str(tmp_path))  # no soffice, no libreoffice
    assert main(["calc", str(source), "-o", str(tmp_path / "out.xlsx"), "--pdf"]) == 2
    assert capsys.readouterr().err == (
        "bearingheat calc: error: --pdf needs LibreOffice (the program soffice or libreoffice, e.g. the Debian "
        "package libreoffice-calc-nogui), which is not installed\n")
    assert not (tmp_path / "out.xlsx").exists()


def test_a_designers_print_setup_is_kept_and_bearingheats_header_is_dated_anew(tmp_path):
    case = CASES["results_sheet_with_print_setup"](tmp_path)  # the designer's margins, page setup and header
    calc_workbook(case.path, in_place=True)
    with zipfile.ZipFile(case.path) as archive:
        xml = archive.read(results_part(case.path, "Results")).decode()
    assert '<pageMargins left="0.2" right="0.2" top="0.5" bottom="0.5" header="0.1" footer="0.1"/>' in xml
    assert '<pageSetup paperSize="9" orientation="portrait" r:id="rId1"/>' in xml
    assert "<oddHeader>&amp;CLosses</oddHeader>" in xml
    start = today()
    plain = make_workbook(tmp_path / "plain.xlsx")
    calc_workbook(plain, in_place=True)
    part = results_part(plain, "Results")
    # the header as a run of another day left it
    edit_package(plain, {part: lambda data: re.sub(rb"(bearingheat [^,<]+, )\d{4}-\d{2}-\d{2}", rb"\g<1>2001-02-03",
                                                   data)})
    with zipfile.ZipFile(plain) as archive:
        assert "2001-02-03</oddHeader>" in archive.read(part).decode()
    calc_workbook(plain, in_place=True)
    with zipfile.ZipFile(plain) as archive:
        xml = archive.read(part).decode()
    assert any(f"{stamp}</oddHeader>" in xml for stamp in stamps_since(start)) and "2001-02-03" not in xml


def test_a_print_area_set_by_hand_covers_the_new_supports(tmp_path):
    """A print area the designer gave the results sheet for 3 supports would leave a 4th off the paper and the
    PDF: the replaced sheet's print area covers every result, and the run says so."""
    path = make_workbook(tmp_path / "area.xlsx", rows=gearbox_rows()[:3])
    calc_workbook(path, in_place=True)
    workbook = openpyxl.load_workbook(path)
    last = openpyxl.utils.get_column_letter(workbook["Results"].max_column)
    workbook["Results"].print_area = f"A1:{last}5"
    workbook["Supports"].append(list(gearbox_rows()[3]))
    workbook.save(path)
    run = calc_workbook(path, in_place=True)
    assert run.notes == [f"the print area of sheet 'Results' ('Results'!$A$1:${last}$5) now covers the results "
                         f"written, Results!$A$1:${last}$6; set it again (Page Layout > Print Area) to print less"]
    assert openpyxl.load_workbook(path)["Results"].print_area == f"'Results'!$A$1:${last}$6"
    assert calc_workbook(path, in_place=True).notes == []  # the same supports again: nothing to say
