"""What the reader must not take at face value: formula values cached by scripts, headers an Excel table renamed,
headers in other letter case, rows of formulas that show "", input columns named like results, units in a CSV."""
from __future__ import annotations

import re
import zipfile
from pathlib import Path

import numpy as np
import openpyxl
import pandas as pd
import pytest
import xlsxwriter
from excel_helpers import HEADER, UNITS, gearbox_rows, make_workbook, require_soffice, set_cached_value
from openpyxl.worksheet.table import Table, TableColumn
from workbook_corpus import edit_package

from bearingheat.calc.table import calc
from bearingheat.errors import ExcelError
from bearingheat.io.excel.libreoffice import convert
from bearingheat.io.excel.opc import office_document, open_package
from bearingheat.io.excel.reader import read_supports
from bearingheat.io.excel.workbook import calc_workbook
from bearingheat.io.tables import calc_csv


def csv_of(rows, tmp_path, header=HEADER, units=UNITS, name="same_rows.csv"):
    """calc on a CSV of the same rows (units in the headers): what the workbook must give."""
    headers = [h if u in ("-", "", None) else f"{h} [{u}]" for h, u in zip(header, units)]
    path = tmp_path / name
    pd.DataFrame(rows, columns=headers).to_csv(path, index=False)
    return calc_csv(path)


def xlsxwriter_book(path, rows, formulas):
    """A workbook a script writes with XlsxWriter: ``formulas`` {cell: (formula, value or None)}; XlsxWriter
    stores 0 for a formula given no value and sets calcPr fullCalcOnLoad."""
    workbook = xlsxwriter.Workbook(str(path))
    ws = workbook.add_worksheet("Supports")
    ws.write_row(0, 0, HEADER)
    ws.write_row(1, 0, UNITS)
    for i, row in enumerate(rows, start=2):
        for j, value in enumerate(row):
            if value is not None:
                ws.write(i, j, value)
    for cell, (formula, value) in formulas.items():
        if value is None:
            ws.write_formula(cell, formula)
        else:
            ws.write_formula(cell, formula, None, value)
    workbook.close()
    return path


UNSAVED = ("{cell}: formula {formula} has no saved value (the file was never opened and saved in a spreadsheet "
           "program); open it in Excel or LibreOffice, save it, and run again")


# ---- 1. a script's cached 0 ---------------------------------------------------------------------------------------

def test_a_formula_cached_as_0_by_xlsxwriter_has_no_saved_value(tmp_path):
    """XlsxWriter stores <v>0</v> for =1.6*2: Fr was read as 0 (MR 90.98 instead of 138.48, status ok)."""
    rows = gearbox_rows()
    path = xlsxwriter_book(tmp_path / "script.xlsx", rows, {"F3": ("=1.6*2", None), "E4": ("=2*1500", None),
                                                              "F5": ("=2*3.1", rows[2][5])})
    assert re.search(rb'<c r="F3"><f>1.6\*2</f><v>0</v></c>', zipped(path, "xl/worksheets/sheet1.xml"))
    assert b'fullCalcOnLoad="1"' in zipped(path, "xl/workbook.xml")
    result = calc_workbook(path).result
    assert result["status"].tolist()[:2] == ["error", "error"]
    assert result["message"].iat[0] == UNSAVED.format(cell="Supports!F3", formula="=1.6*2")
    assert result["message"].iat[1].startswith(UNSAVED.format(cell="Supports!E4", formula="=2*1500") + "; ")
    assert result["MR [N*mm]"].iloc[:2].isna().all()
    expected = csv_of(rows, tmp_path)  # the value a script gave (6.2 for =2*3.1) is read
    np.testing.assert_allclose(result["MR [N*mm]"].iloc[2:], expected["MR [N*mm]"].iloc[2:], rtol=1e-12)
    assert (result["status"].iloc[2:] == expected["status"].iloc[2:]).all()


def test_a_workbook_part_of_another_name_is_found_by_the_reader_and_the_package_edit(tmp_path):
    """The workbook part is where _rels/.rels says (xl/book.xml here): the reader finds its recalculation flag
    there (F3's cached 0 has no saved value), and the package edit edits it."""
    path = xlsxwriter_book(tmp_path / "moved.xlsx", gearbox_rows(), {"F3": ("=1.6*2", None)})
    with zipfile.ZipFile(path) as archive:
        workbook, workbook_rels = archive.read("xl/workbook.xml"), archive.read("xl/_rels/workbook.xml.rels")
    edit_package(path, {"_rels/.rels": lambda data: data.replace(b'Target="xl/workbook.xml"', b'Target="xl/book.xml"'),
                        "[Content_Types].xml": lambda data: data.replace(b"/xl/workbook.xml", b"/xl/book.xml")},
                 add={"xl/book.xml": workbook, "xl/_rels/book.xml.rels": workbook_rels},
                 remove=("xl/workbook.xml", "xl/_rels/workbook.xml.rels"))
    rels = zipped(path, "_rels/.rels")
    office = "http://schemas.openxmlformats.org/officeDocument/2006/relationships/officeDocument"
    assert office_document(rels, path) == (office, "xl/book.xml")
    assert office_document(rels.replace(b"/officeDocument", b"/extended-properties"), path) is None
    assert office_document(None, path) is None
    assert open_package(path).workbook == "xl/book.xml"
    assert calc_workbook(path).result["message"].iat[0] == UNSAVED.format(cell="Supports!F3", formula="=1.6*2")
    calc_workbook(path, in_place=True)
    assert b'name="Results"' in zipped(path, "xl/book.xml")
    assert "xl/workbook.xml" not in zipfile.ZipFile(path).namelist()


def test_a_cached_0_is_read_where_no_recalculation_is_asked_for(tmp_path):
    """Excel and LibreOffice drop fullCalcOnLoad when they save: their cached 0 is a value (Fa =0*1 is 0)."""
    rows = gearbox_rows()
    rows[0][6] = 0
    path = xlsxwriter_book(tmp_path / "saved.xlsx", rows, {"G3": ("=0*1", None)})
    edit_package(path, {"xl/workbook.xml": lambda data: data.replace(b' fullCalcOnLoad="1"', b"")})
    result = calc_workbook(path).result
    expected = csv_of(rows, tmp_path)
    np.testing.assert_allclose(result["MR [N*mm]"], expected["MR [N*mm]"], rtol=1e-12)
    assert result["status"].tolist() == expected["status"].tolist()


def test_bearingheats_own_recalculation_flag_leaves_cached_values_read(tmp_path):
    """--in-place sets fullCalcOnLoad and marks the workbook: a saved 0 among other values stays a value; a
    script's workbook whose every formula still caches 0 stays without saved values."""
    rows = gearbox_rows()
    rows[0][6] = 0
    path = xlsxwriter_book(tmp_path / "saved.xlsx", rows, {"G3": ("=0*1", None), "F4": ("=1.5*1", rows[1][5])})
    edit_package(path, {"xl/workbook.xml": lambda data: data.replace(b' fullCalcOnLoad="1"', b"")})
    calc_workbook(path, in_place=True)
    assert b'fullCalcOnLoad="1"' in zipped(path, "xl/workbook.xml")
    result = calc_workbook(path).result
    np.testing.assert_allclose(result["MR [N*mm]"], csv_of(rows, tmp_path)["MR [N*mm]"], rtol=1e-12)

    script = xlsxwriter_book(tmp_path / "script.xlsx", gearbox_rows(), {"F3": ("=1.6*2", None)})
    calc_workbook(script, in_place=True)
    assert calc_workbook(script).result["message"].iat[0] == UNSAVED.format(cell="Supports!F3", formula="=1.6*2")


def zipped(path, member):
    with zipfile.ZipFile(path) as archive:
        return archive.read(member)


# ---- 2. headers an Excel table renamed ----------------------------------------------------------------------------

RENAMED = ("Supports!D1: header {header!r} looks like 'D' renamed by Excel, which renames a table header that repeats "
           "another one without regard to letter case ('d' and 'D' -> 'D2'); calc would not read it and would take D "
           "as not given. Make the headers differ beyond letter case (e.g. 'd' and 'D [mm]', mm under d in the units "
           "row), or convert the table to a range")


@pytest.mark.parametrize("header, unit", [("D2", "mm"), ("D [mm]2", "-"), ("d2", "mm")])
def test_a_header_renamed_by_an_excel_table_is_refused(tmp_path, header, unit):
    """calc passed 'D2' through unread and took the catalogue's D (MR 138.48 ok where the CSV gives 162.36)."""
    names, units = list(HEADER), list(UNITS)
    names[3], units[3] = header, unit
    path = make_workbook(tmp_path / "table.xlsx", header=names, units=units)
    with pytest.raises(ExcelError, match=f"^{re.escape(RENAMED.format(header=header))}$"):
        read_supports(path)


def test_contract_names_ending_in_digits_are_read(tmp_path):
    names, units = list(HEADER), list(UNITS)
    names[10:13], units[10:13] = ["d1", "D1", "nu40"], ["mm", "mm", "mm^2/s"]
    rows = [row[:10] + [None, None, None] for row in gearbox_rows()]
    table, info = read_supports(make_workbook(tmp_path / "digits.xlsx", header=names, units=units, rows=rows))
    assert info.headers["d1"] == "d1" and info.headers["nu40"] == "nu40"
    names[10] = "spare2"
    _, info = read_supports(make_workbook(tmp_path / "other.xlsx", header=names, units=units, rows=rows))
    assert info.letters["spare2"] == "K"


def test_the_form_the_refusal_suggests_is_read(tmp_path):
    names, units = list(HEADER), list(UNITS)
    names[3] = "D [mm]"
    rows = gearbox_rows()
    table, info = read_supports(make_workbook(tmp_path / "table.xlsx", header=names, units=units, rows=rows))
    assert info.headers["D"] == "D [mm]" and info.unit_of("d") == "mm"


# ---- 3. text headers in other letter case -------------------------------------------------------------------------

LOOKS_LIKE = ("Supports!{cell}: column {header!r} looks like {meant!r}, which calc would not read from it: name it "
              "{meant!r} (headers are 'name [unit]', the name in its own letters); as it is, the table would be "
              "computed as if {meant} were not given")


@pytest.mark.parametrize("header, cell", [("Arrangement", "J1"), ("Designation", "B1"), ("Lubrication", "I1")])
def test_a_text_header_in_other_letter_case_is_refused_naming_its_cell(tmp_path, header, cell):
    """'Arrangement' = paired was passed through and the pair computed as a single bearing, status ok."""
    names = [header if name == header.lower() else name for name in HEADER]
    path = make_workbook(tmp_path / "case.xlsx", header=names)
    message = LOOKS_LIKE.format(cell=cell, header=header, meant=header.lower())
    with pytest.raises(ExcelError, match=f"^{re.escape(message)}$"):
        calc_workbook(path)


@pytest.mark.parametrize("header", ["Model", "Type", "Series"])
def test_an_added_text_column_in_other_letter_case_is_refused(tmp_path, header):
    rows = [row + ["x"] for row in gearbox_rows()]
    path = make_workbook(tmp_path / "case.xlsx", header=HEADER + [header], units=UNITS + ["-"], rows=rows)
    message = LOOKS_LIKE.format(cell="N1", header=header, meant=header.lower())
    with pytest.raises(ExcelError, match=f"^{re.escape(message)}$"):
        calc_workbook(path)


# ---- 4. rows of formulas that show "" -----------------------------------------------------------------------------

def test_rows_of_formulas_that_show_empty_text_are_blank(tmp_path):
    """A sheet pre-filled with =IF(Data!A5="","",Data!A5) down to row 10 gave 5 error rows and exit 1."""
    rows = gearbox_rows()[:3]
    blank = [f'=IF(Data!{letter}5="","",Data!{letter}5)' for letter in "ABCDEFGHIJKLM"]
    path = make_workbook(tmp_path / "prefilled.xlsx", rows=rows + [blank] * 5)
    workbook = openpyxl.load_workbook(path)
    workbook.create_sheet("Data")
    workbook.save(path)
    # as Excel and LibreOffice save them: an empty text (t="str", an empty <v>)
    edit_package(path, {"xl/worksheets/sheet1.xml": lambda data: re.sub(
        rb'<c r="([A-M](?:[6-9]|10))"([^>]*)><f>([^<]*)</f><v\s*/?>(</v>)?', rb'<c r="\1"\2 t="str"><f>\3</f><v></v>',
        data)})
    table, info = read_supports(path)
    assert info.rows == [3, 4, 5] and info.uncached == []
    assert all(row <= 5 for _, row in info.formula_cells)
    result = calc_workbook(path).result
    expected = csv_of(rows, tmp_path)
    np.testing.assert_allclose(result["MR [N*mm]"], expected["MR [N*mm]"], rtol=1e-12)
    assert result["status"].tolist() == expected["status"].tolist()


@pytest.mark.integration
def test_rows_of_formulas_saved_by_libreoffice_as_empty_text_are_blank(tmp_path):
    """The auditor's sheet: every cell of rows 3-10 pulls from a sheet Data that has 3 supports."""
    require_soffice()
    rows = gearbox_rows()[:3]
    workbook = openpyxl.Workbook()
    ws = workbook.active
    ws.title = "Supports"
    data = workbook.create_sheet("Data")
    ws.append(HEADER)
    ws.append(UNITS)
    for row in rows:
        data.append(row)
    for i in range(8):
        for j, letter in enumerate("ABCDEFGHIJKLM", start=1):
            ws.cell(3 + i, j).value = f'=IF(Data!{letter}{i + 1}="","",Data!{letter}{i + 1})'
    workbook.save(tmp_path / "pulled.xlsx")
    path = convert([tmp_path / "pulled.xlsx"], "xlsx", tmp_path / "saved")[0]
    table, info = read_supports(path)
    assert info.rows == [3, 4, 5] and info.uncached == []
    result = calc_workbook(path).result
    expected = csv_of(rows, tmp_path)
    np.testing.assert_allclose(result["MR [N*mm]"], expected["MR [N*mm]"], rtol=1e-12)
    assert result["status"].tolist() == expected["status"].tolist()


def test_a_row_with_a_formula_never_saved_is_not_blank(tmp_path):
    rows = gearbox_rows()[:2] + [['=IF(Data!A5="","",Data!A5)'] + [None] * (len(HEADER) - 1)]
    path = make_workbook(tmp_path / "unsaved.xlsx", rows=rows)
    table, info = read_supports(path)
    assert info.rows == [3, 4, 5] and [(p, h) for p, h, _ in info.uncached] == [(2, "id")]


# ---- 5. input columns named like results --------------------------------------------------------------------------

@pytest.mark.parametrize("header, name", [("status", "status"), ("message", "message"), ("MR [N*mm]", "MR"),
                                          ("NR", "NR")])
def test_an_input_column_named_like_a_result_is_refused(tmp_path, header, name):
    """calc writes that column: the designer's status (released/draft) was replaced by ok/error or hidden."""
    rows = [row + ["released"] for row in gearbox_rows()]
    path = make_workbook(tmp_path / "named.xlsx", header=HEADER + [header], units=UNITS + ["-"], rows=rows)
    message = f"Supports!N1: {header!r} is a column calc writes; rename it (e.g. '{name} (design)')"
    with pytest.raises(ExcelError, match=f"^{re.escape(message)}$"):
        read_supports(path)


def test_the_suggested_name_is_passed_through(tmp_path):
    rows = [row + ["released"] for row in gearbox_rows()]
    path = make_workbook(tmp_path / "named.xlsx", header=HEADER + ["status (design)"], units=UNITS + ["-"],
                         rows=rows)
    result = calc_workbook(path, tmp_path / "out.csv").result
    assert result["status (design)"].tolist() == ["released"] * 6
    assert pd.read_csv(tmp_path / "out.csv")["status (design)"].tolist() == ["released"] * 6


# ---- 6. units of the units row in a CSV ---------------------------------------------------------------------------

def test_a_csv_of_a_workbook_has_the_units_in_its_headers_and_reads_back(tmp_path):
    """The CSV had 'd,D,n,Fr' over kN and rpm and no unit anywhere; read back: "column 'd': needs a unit"."""
    path = make_workbook(tmp_path / "in.xlsx")
    out = tmp_path / "out.csv"
    run = calc_workbook(path, out)
    written = pd.read_csv(out)
    # (a dimensionless column needs no unit: 'Y', not 'Y [1]')
    assert list(written.columns[:13]) == [h if u in ("-", "1") else f"{h} [{u}]" for h, u in zip(HEADER, UNITS)]
    assert list(run.result.columns[:3]) == ["id", "designation", "d"]  # the result keeps the sheet's headers
    np.testing.assert_array_equal(written["Fr [kN]"], [row[5] for row in gearbox_rows()])
    again = calc_csv(out)
    np.testing.assert_allclose(again["MR [N*mm]"], run.result["MR [N*mm]"], rtol=1e-12)
    assert again["status"].tolist() == run.result["status"].tolist()
    np.testing.assert_allclose(again["MR [N*mm]"], calc(pd.read_csv(out))["MR [N*mm]"], rtol=1e-12)


# ---- 7. numbers typed as text with groups of three digits ----------------------------------------------------------

AMBIGUOUS = ("{cell}: {text!r} is a number stored as text, and its {mark!r} may be a decimal mark or a thousands "
             "separator; type the number into the cell as a number")


def test_a_number_as_text_that_reads_two_ways_is_refused_in_a_workbook(tmp_path):
    """'3.000' in Fr was read as 3 kN (status ok), while '3,000' and '3 000' were refused: a workbook cell has no
    decimal mark of its own to say whether 3 or 3000 was meant. Text that reads one way is read as before."""
    rows = gearbox_rows()
    texts = {0: ("F", "3.000"), 1: ("F", "12,500"), 2: ("E", "1.234.567"), 3: ("F", " +3.000 ")}
    for position, (letter, text) in texts.items():
        rows[position][HEADER.index({"F": "Fr", "E": "n"}[letter])] = text
    rows[4][HEADER.index("Fr")] = "0.500"  # 0.5 whichever the mark: no thousands group begins with 0
    rows[5][HEADER.index("Fr")] = "3.0000"  # four decimals: no thousands separator
    result = calc_workbook(make_workbook(tmp_path / "text.xlsx", rows=rows)).result
    for position, (letter, text) in texts.items():
        mark = "." if "." in text else ","
        expected = AMBIGUOUS.format(cell=f"Supports!{letter}{position + 3}", text=text, mark=mark)
        assert result["status"].iat[position] == "error"
        assert result["message"].iat[position].split("; ")[:2] == expected.split("; "), position
    assert result["MR [N*mm]"].iloc[:4].isna().all()
    numbers = gearbox_rows()
    numbers[4][HEADER.index("Fr")], numbers[5][HEADER.index("Fr")] = 0.5, 3.0
    expected = csv_of(numbers, tmp_path)
    np.testing.assert_allclose(result["MR [N*mm]"].iloc[4:], expected["MR [N*mm]"].iloc[4:], rtol=1e-12)
    assert result["status"].iloc[4:].tolist() == expected["status"].iloc[4:].tolist()
    # two different marks: both named
    rows = gearbox_rows()
    rows[0][HEADER.index("Fr")] = "1,234.500"
    message = calc_workbook(make_workbook(tmp_path / "mixed.xlsx", rows=rows)).result["message"].iat[0]
    assert message.startswith("Supports!F3: '1,234.500' is a number stored as text, and its ',' and '.' may be "
                              "decimal marks or thousands separators; type the number into the cell as a number")


def test_a_csv_reads_3_000_with_its_decimal_mark_as_before(tmp_path):
    """In a CSV '3.000' is read with the file's decimal mark (the point): 3 kN, as the number 3."""
    rows = gearbox_rows()
    rows[0][HEADER.index("Fr")] = "3.000"
    as_text = csv_of(rows, tmp_path, name="text.csv")
    rows[0][HEADER.index("Fr")] = 3.0
    as_number = csv_of(rows, tmp_path, name="number.csv")
    assert as_text["status"].iat[0] == "ok"
    assert as_text["MR [N*mm]"].iat[0] == as_number["MR [N*mm]"].iat[0]


# ---- 8. the totals row of an Excel table --------------------------------------------------------------------------

def table_with_totals(path, cached: dict[str, str]) -> Path:
    """The gearbox supports as an Excel table 'Loads' (units row inside it) with its totals row shown: 'Total'
    under id, SUBTOTAL of Fr and Fa; ``cached``: the values Excel saved for those formulas ({cell: value})."""
    header = [h if h != "D" else "D [mm]" for h in HEADER]  # (Excel renames 'D' beside 'd' in a table: 'D2')
    make_workbook(path, header)
    workbook = openpyxl.load_workbook(path)
    ws = workbook["Supports"]
    last = 3 + len(gearbox_rows())
    ws[f"A{last}"], ws[f"F{last}"], ws[f"G{last}"] = "Total", "=SUBTOTAL(109,Loads[Fr])", "=SUBTOTAL(109,Loads[Fa])"
    table = Table(displayName="Loads", ref=f"A1:M{last}", totalsRowCount=1)
    table.tableColumns = [TableColumn(id=i, name=name) for i, name in enumerate(header, start=1)]
    table.tableColumns[0].totalsRowLabel = "Total"
    table.tableColumns[5].totalsRowFunction = table.tableColumns[6].totalsRowFunction = "sum"
    ws.add_table(table)
    workbook.save(path)
    for cell, value in cached.items():
        set_cached_value(path, 1, cell, value)
    return Path(path)


@pytest.mark.parametrize("cached", [{"F9": "20.8", "G9": "5.3"}, {}])
def test_the_totals_row_of_an_excel_table_is_no_support(tmp_path, cached):
    """Row 9, the table's totals row (totalsRowCount="1"), was read as a seventh support 'Total' (an error row,
    or with saved values one of Fr 20.8 kN); it is left out with a note. Saved or not, its formulas are not read."""
    path = table_with_totals(tmp_path / "table.xlsx", cached)
    part = zipped(path, "xl/tables/table1.xml").decode()
    assert re.search(r'<table [^>]*ref="A1:M9"[^>]*totalsRowCount="1"', part)
    assert '<tableColumn id="6" name="Fr" totalsRowFunction="sum"/>' in part
    run = calc_workbook(path, tmp_path / "out.xlsx")
    assert run.info.rows == [3, 4, 5, 6, 7, 8] and run.info.totals_rows == [(9, "Loads")]
    assert run.notes == ["row 9 of sheet 'Supports' is the totals row of the Excel table 'Loads', not a support: "
                         "it was left out"]
    plain = calc_workbook(make_workbook(tmp_path / "plain.xlsx")).result
    np.testing.assert_allclose(run.result["MR [N*mm]"], plain["MR [N*mm]"], rtol=1e-12)
    assert run.result["status"].tolist() == plain["status"].tolist() == ["ok"] * 4 + ["warning", "ok"]
    results = openpyxl.load_workbook(tmp_path / "out.xlsx")["Results"]
    assert [row[0] for row in results.iter_rows(min_row=3, values_only=True)] == [3, 4, 5, 6, 7, 8]
