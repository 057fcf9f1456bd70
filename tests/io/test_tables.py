"""CSV tables of supports: read for calc, results written back; an unreadable file is an InputError naming it."""
from __future__ import annotations

import re

import pandas as pd
import pyarrow as pa
import pytest
from excel_helpers import EXAMPLE_CSV, csv_result

import bearingheat as bh
from bearingheat.cli import main
from bearingheat.errors import InputError
from bearingheat.io.tables import calc_csv, cite_rows, escape_formulas, read_csv, sniff_format, write_csv


def test_read_csv_ignores_spaces_after_commas(tmp_path):
    path = tmp_path / "in.csv"
    path.write_text("designation, d [mm], lubrication\n6208, 40, oil_bath\n")
    table = read_csv(path)
    assert list(table.columns) == ["designation", "d [mm]", "lubrication"]
    assert table.loc[0, "lubrication"] == "oil_bath" and table.loc[0, "d [mm]"] == 40


def test_unreadable_csv_is_an_input_error(tmp_path, capsys):
    path = tmp_path / "empty.csv"
    path.write_text("")
    with pytest.raises(InputError, match=re.escape(f"{path}: not a readable CSV (")):
        read_csv(path)
    assert main(["calc", str(path)]) == 2
    assert capsys.readouterr().err.startswith(f"bearingheat calc: error: {path}: not a readable CSV (")


def test_write_csv_round_trip(tmp_path):
    result = csv_result()
    written = write_csv(result, tmp_path / "out.csv")
    back = pd.read_csv(written)
    assert list(back.columns) == list(result.columns)
    pd.testing.assert_series_equal(back["MR [N*mm]"], result["MR [N*mm]"], rtol=1e-15)
    assert len(pd.read_csv(EXAMPLE_CSV)) == len(back)


# ---- separators, decimal marks, encodings --------------------------------------------------------------------

HEAD = ["id", "designation", "d [mm]", "D [mm]", "C0 [kN]", "lubrication", "n [rpm]", "Fr [kN]", "nu [mm^2/s]"]
ROW = ["spindle rear", "6205", "25", "52", "7.8", "oil_bath", "3000", "2.5", "12.5"]


def _write(path, sep=",", decimal=".", rows=(ROW,), header=HEAD, encoding="utf-8"):
    lines = [sep.join(header)] + [sep.join(c.replace(".", decimal) for c in row) for row in rows]
    path.write_text("\n".join(lines) + "\n", encoding=encoding)
    return path


@pytest.mark.parametrize("sep, decimal", [(",", "."), (";", ","), (";", "."), ("\t", "."), ("\t", ",")])
def test_separator_and_decimal_mark_are_found(tmp_path, sep, decimal):
    path = _write(tmp_path / "in.csv", sep, decimal)
    table = read_csv(path)
    assert list(table.columns) == HEAD
    assert table.loc[0, "Fr [kN]"] == 2.5 and table.loc[0, "nu [mm^2/s]"] == 12.5 and table.loc[0, "C0 [kN]"] == 7.8


def test_sniff_format():
    assert sniff_format("a;b;c\n1,5;2;3\n") == (";", ",")
    assert sniff_format("a;b;c\n1.5;2;3\n") == (";", ".")
    assert sniff_format('"x;y",b,c\n1,2,3\n') == (",", ".")
    assert sniff_format("a\tb\n1,5\t2\n") == ("\t", ",")
    assert sniff_format("a\n1\n") == (",", ".")


def test_sep_and_decimal_can_be_given(tmp_path):
    path = tmp_path / "in.csv"
    path.write_text("designation;n [rpm]\n6205;1,5\n")
    assert read_csv(path, sep=";", decimal=",").loc[0, "n [rpm]"] == 1.5
    assert read_csv(path, sep=";", decimal=".").loc[0, "n [rpm]"] == "1,5"
    with pytest.raises(InputError) as exc:
        read_csv(path, sep=",", decimal=",")
    assert str(exc.value) == "--decimal ',' is also the separator; give --sep ';' or --sep tab with it"


def test_unreadable_csv_names_the_separator_and_the_options(tmp_path, capsys):
    path = tmp_path / "in.csv"
    path.write_text("a,b\n1,2\n3,4,5\n")
    message = (f"{path}: not a readable CSV (line 3 has 3 fields, the header 2); its columns were read as separated "
               "by comma ',' with decimal mark '.': if the file uses another separator or decimal commas, give --sep "
               "(',', ';' or tab) and --decimal (',' or '.')")
    with pytest.raises(InputError) as exc:
        read_csv(path)
    assert str(exc.value) == message
    assert main(["calc", str(path)]) == 2
    assert capsys.readouterr().err == f"bearingheat calc: error: {message}\n"


def test_european_csv_runs_through_calc(tmp_path, capsys):
    comma = _write(tmp_path / "comma.csv")
    euro = _write(tmp_path / "euro.csv", ";", ",")
    out_comma, out_euro = tmp_path / "a.csv", tmp_path / "b.csv"
    assert main(["calc", str(comma), "-o", str(out_comma), "-q"]) == 0
    assert main(["calc", str(euro), "-o", str(out_euro), "-q"]) == 0
    pd.testing.assert_frame_equal(pd.read_csv(out_comma), pd.read_csv(out_euro))


@pytest.mark.parametrize("encoding", ["utf-8-sig", "utf-16", "cp1252"])
def test_encodings(tmp_path, encoding):
    row = ["Lager vorn (Öl)", *ROW[1:]]
    path = _write(tmp_path / "in.csv", ";", ",", rows=(row,), encoding=encoding)
    table = read_csv(path)
    assert table.loc[0, "id"] == "Lager vorn (Öl)" and table.loc[0, "Fr [kN]"] == 2.5


def test_binary_and_undecodable_files(tmp_path, capsys):
    binary = tmp_path / "book.csv"
    binary.write_bytes(b"PK\x03\x04\x00\x00garbage")
    with pytest.raises(InputError) as exc:
        read_csv(binary)
    assert str(exc.value) == f"{binary}: not a CSV text file (it holds binary data; is it a workbook with the wrong name?)"
    bad = tmp_path / "bad.csv"
    bad.write_bytes(b"id,n [rpm]\n\x81\x8d,1\n")
    assert main(["calc", str(bad)]) == 2
    assert capsys.readouterr().err == (f"bearingheat calc: error: {bad}: not a readable CSV (byte 0x81 at position 11 "
                                       "is not UTF-8 text); save it as 'CSV UTF-8'\n")


# ---- columns -------------------------------------------------------------------------------------------------

def test_duplicated_column_is_named_by_its_header(tmp_path, capsys):
    path = _write(tmp_path / "in.csv", header=[*HEAD, "Fr [kN]"], rows=([*ROW, "3"],))
    assert main(["calc", str(path)]) == 2
    assert capsys.readouterr().err == (f"bearingheat calc: error: {path}: column 'Fr [kN]' appears twice (columns 8 "
                                       "and 10); keep one\n")


def test_unknown_columns_pass_through_untouched(tmp_path):
    header = [HEAD[0], "a[b]c", *HEAD[1:], "[internal]", "note [see p. 3]", "code"]
    path = tmp_path / "in.csv"
    pd.DataFrame([[ROW[0], "x]y", *ROW[1:], "=cmd", "12.50", "007"]], columns=header).to_csv(path, index=False)
    result = calc_csv(path)
    assert list(result.columns[:len(header)]) == header
    assert result.loc[0, "status"] == "ok"
    assert [result.loc[0, c] for c in ("a[b]c", "[internal]", "note [see p. 3]", "code")] == ["x]y", "=cmd", "12.50",
                                                                                             "007"]


def test_header_only_csv_is_no_supports(tmp_path, capsys):
    path = tmp_path / "in.csv"
    path.write_text(",".join(HEAD) + "\n")
    with pytest.raises(InputError) as exc:
        read_csv(path)
    assert str(exc.value) == f"{path}: no supports (only a header row)"
    assert main(["calc", str(path)]) == 2
    assert capsys.readouterr().err == f"bearingheat calc: error: {path}: no supports (only a header row)\n"


# ---- row numbers -------------------------------------------------------------------------------------------------

def test_row_messages_cite_the_line_of_the_file(tmp_path, capsys):
    path = tmp_path / "in.csv"
    path.write_text(",".join(HEAD) + "\n"
                    + ",".join(ROW) + "\n"
                    + "\n"                                                        # line 3: blank, skipped
                    + '"two\nlines",6205,25,52,7.8,oil_bath,3000,abc,12\n'         # lines 4-5
                    + ",6205,25,52,7.8,oil_bath,-10,2,12\n"                        # line 6: no id
                    + "spindle rear,6Z05,25,52,7.8,oil_bath,3000,2,12\n")          # line 7
    out = tmp_path / "out.csv"
    assert main(["calc", str(path), "-o", str(out)]) == 1
    messages = pd.read_csv(out, keep_default_na=False)["message"].tolist()
    assert messages[0] == ""
    assert messages[1] == "row 4 (id \"two\nlines\"): 'abc' is not a number for Fr [kN]"
    assert messages[2] == "row 6: n [rpm]: -10 must be >= 0 (speed magnitude)"
    assert messages[3] == ('row 7 (id "spindle rear"): designation: \'6Z05\' matches no row of the Schaeffler catalogue tables '
                           "(close matches: 6405, 6305, 6205, 6015, 6005); give type and series explicitly instead")
    printed = capsys.readouterr().out
    assert ('error: row 7 (id "spindle rear"): designation: \'6Z05\' matches no row of the Schaeffler catalogue tables'
            in printed)


def test_cite_rows_leaves_rows_without_a_message(tmp_path):
    result = pd.DataFrame({"id": ["a", None], "message": ["", "bad"]})
    assert cite_rows(result, [2, 9])["message"].tolist() == ["", "row 9: bad"]
    assert cite_rows(pd.DataFrame({"message": ["bad"]}), None)["message"].tolist() == ["bad"]


# ---- CSV injection -----------------------------------------------------------------------------------------------

def test_escape_formulas_text_only():
    frame = pd.DataFrame({"=head": ["=1+1", "+A1", "-2+3", "@SUM(A1)", "\tx", "\rx", "-3.2", "+5", "1e-3", "ok", None],
                          "x": [-3.2, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10]})
    out = escape_formulas(frame)
    assert list(out.columns) == ["'=head", "x"]
    assert out["'=head"].tolist()[:-1] == ["'=1+1", "'+A1", "'-2+3", "'@SUM(A1)", "'\tx", "'\rx", "-3.2", "+5",
                                           "1e-3", "ok"]
    assert pd.isna(out["'=head"].iloc[-1])
    assert out["x"].tolist() == frame["x"].tolist()
    assert frame.loc[0, "=head"] == "=1+1"  # the input is not changed


def test_write_csv_escapes_unless_told_not_to(tmp_path):
    frame = pd.DataFrame({"id": ["=HYPERLINK(\"http://x\")", "a"], "M [N*mm]": [-3.2, 4.0]})
    write_csv(frame, tmp_path / "a.csv")
    assert (tmp_path / "a.csv").read_text() == 'id,M [N*mm]\n"\'=HYPERLINK(""http://x"")",-3.2\na,4.0\n'
    write_csv(frame, tmp_path / "b.csv", escape=False)
    assert (tmp_path / "b.csv").read_text() == 'id,M [N*mm]\n"=HYPERLINK(""http://x"")",-3.2\na,4.0\n'


def test_calc_escapes_csv_cells_and_no_csv_escape_turns_it_off(tmp_path):
    path = _write(tmp_path / "in.csv", rows=(["=1+2", *ROW[1:]], ["@cmd", *ROW[1:]]))
    escaped, plain = tmp_path / "escaped.csv", tmp_path / "plain.csv"
    assert main(["calc", str(path), "-o", str(escaped), "-q"]) == 0
    assert main(["calc", str(path), "-o", str(plain), "-q", "--no-csv-escape"]) == 0
    assert pd.read_csv(escaped)["id"].tolist() == ["'=1+2", "'@cmd"]
    assert pd.read_csv(plain)["id"].tolist() == ["=1+2", "@cmd"]
    assert pd.read_csv(escaped)["Fr [kN]"].tolist() == [2.5, 2.5]


def test_text_columns_are_read_as_text(tmp_path):
    path = tmp_path / "in.csv"
    path.write_text("id,designation,series,n [rpm],code\n007,6205,02,1500,0042\n")
    table = read_csv(path)
    assert [table.loc[0, c] for c in ("id", "designation", "series", "code")] == ["007", "6205", "02", "0042"]
    assert table.loc[0, "n [rpm]"] == 1500


# ---- big tables: pyarrow's reader, the row lines in arrays, the CSV text from Arrow --------------------------------

def test_pyarrow_and_pandas_read_a_file_alike(tmp_path):
    """A file without spaces after its separators goes to pyarrow's reader, the same file with them to pandas'
    parser: the same table, numbers, text, blanks and pandas' missing-value words alike."""
    rows = ["id;designation;d [mm];n [rpm];Fr [kN];Y0;note", "a;6208;40;1500,5;2;;NA", "b;6209;45;NA;2,5;;x",
            '"c;d";NU208-E;40;900;3;;007']
    tight, spaced = tmp_path / "tight.csv", tmp_path / "spaced.csv"
    tight.write_text("\n".join(rows) + "\n")
    spaced.write_text("\n".join(row.replace(";", "; ") if not row.startswith('"') else row for row in rows) + "\n")
    fast, slow = read_csv(tight), read_csv(spaced)
    pd.testing.assert_frame_equal(fast, slow, check_exact=True)
    assert fast["n [rpm]"].tolist()[0] == 1500.5 and pd.isna(fast["n [rpm]"].tolist()[1])
    assert fast["Y0"].dtype == "float64" and fast["note"].tolist()[2] == "007" and fast["id"].tolist()[2] == "c;d"
    assert list(fast.attrs["lines"]) == [2, 3, 4]


def test_a_column_whose_type_changes_after_the_first_block_is_read_whole(tmp_path):
    """A column's type is the type of the whole file, not of its first block (1 MB): a number with a decimal
    point or a word far down the file loses no row and cuts no number."""
    path = tmp_path / "long.csv"
    rows = 150_000  # 2 MB: two blocks
    loads = ["2"] * rows
    loads[-1] = "2.75"
    speeds = ["1500"] * rows
    speeds[-2] = "fast"
    path.write_text("id,Fr [kN],n [rpm]\n" + "".join(f"s{i},{loads[i]},{speeds[i]}\n" for i in range(rows)))
    table = read_csv(path)
    assert len(table) == rows and table["Fr [kN]"].iloc[-1] == 2.75 and table["Fr [kN]"].dtype == "float64"
    assert table["n [rpm]"].iloc[-2] == "fast" and table["n [rpm]"].iloc[0] == "1500"
    assert table.attrs["lines"][rows - 1] == rows + 1


def test_row_lines_of_an_unquoted_file_skip_blank_lines(tmp_path):
    path = tmp_path / "in.csv"
    path.write_text("\n" + ",".join(HEAD) + "\r\n" + ",".join(ROW) + "\r\n  \r\n\r\n"
                    + "x,6205,25,52,7.8,oil_bath,3000,abc,12\r\n")
    table = read_csv(path)
    assert list(table.attrs["lines"]) == [3, 6]
    result = calc_csv(path)
    assert result["message"].tolist()[1] == "row 6 (id \"x\"): 'abc' is not a number for Fr [kN]"


def test_row_lines_are_not_copied_by_every_operation():
    """pandas deep-copies DataFrame.attrs on every operation: the row lines give themselves as their copy."""
    import copy

    from bearingheat.io.tables import RowLines
    lines = RowLines(range(2, 100_002))
    frame = pd.DataFrame({"x": range(100_000)})
    frame.attrs["lines"] = lines
    assert copy.deepcopy(lines) is lines and (frame + 1).attrs["lines"] is lines
    assert lines[10:12] == RowLines([12, 13]) and lines[0] == 2 and len(lines) == 100_000


def test_write_csv_writes_the_text_of_pandas_to_csv(tmp_path):
    """The CSV text built from Arrow arrays is pandas' to_csv(index=False) text, byte for byte: floats of every
    magnitude (Python's repr), whole floats with '.0', quotes only where a cell needs them, formulas escaped."""
    import numpy as np
    rng = np.random.default_rng(5)
    numbers = rng.normal(size=3000) * 10.0 ** rng.integers(-12, 22, 3000)
    numbers[::9] = np.round(numbers[::9])
    numbers[::13] = np.nan
    frame = pd.DataFrame({"id": [f"s{i}" if i % 5 else f'=cmd|"x, y"|{i}' for i in range(3000)],
                          "MR [N*mm]": numbers, "n [rpm]": np.arange(3000), "flag": [True, False, True] * 1000,
                          "message": ["" if i % 7 else f"row {i}: Fr [kN]; check\nit" for i in range(3000)]})
    frame.loc[3, "message"] = None
    write_csv(frame, tmp_path / "out.csv")
    assert (tmp_path / "out.csv").read_text() == escape_formulas(frame).to_csv(index=False)
    write_csv(frame, tmp_path / "raw.csv", escape=False)
    assert (tmp_path / "raw.csv").read_text() == frame.to_csv(index=False)


def test_numbers_left_as_text_are_read_with_the_files_decimal_mark(tmp_path):
    """A cell pyarrow cannot read as a number leaves its column as text; calc then reads the column's numbers with
    the file's decimal mark: with decimal commas '3,2' is 3.2 and '1.480' (a grouped 1480?) no number, never
    1.48; with decimal points '3,2' is no number, and the message says which mark was used."""
    head = "id;designation;lubrication;n [rpm];Fr [kN];Fa [kN];nu [mm^2/s]\n"
    path = tmp_path / "comma.csv"
    path.write_text(head + "a;6208;oil_bath;1.480;3,2;0,9;40\nb;6208;oil_bath;1480;3,2;0,9;40\n"
                           "c;6208;oil_bath;1480;tbd;0,9;40\n")
    out = calc_csv(path, decimal=",")
    assert out["status"].tolist() == ["error", "ok", "error"]
    assert out["message"].iat[0].startswith("row 2 (id \"a\"): '1.480' is not a number for n [rpm] (the decimal mark "
                                            "is ',')")
    assert out["message"].iat[2] == "row 4 (id \"c\"): 'tbd' is not a number for Fr [kN]"
    assert out["MR [N*mm]"].iat[1] == pytest.approx(138.478, abs=5e-4)  # Fr = 3.2 kN, as the demo's 6208
    assert main(["calc", str(path), "--decimal", ",", "-o", str(tmp_path / "out.parquet"), "-q"]) == 1  # in blocks
    blocks = pd.read_parquet(tmp_path / "out.parquet")
    assert blocks["message"].tolist() == out["message"].tolist()
    assert blocks["MR [N*mm]"].iat[1] == out["MR [N*mm]"].iat[1]
    path.write_text(head + "a;6208;oil_bath;1.480;3,2;0,9;40\n")  # one point number: the file reads with points
    message = calc_csv(path)["message"].iat[0]
    assert message == ("row 2 (id \"a\"): '3,2' is not a number for Fr [kN] (the decimal mark is '.'); '0,9' is not a "
                       "number for Fa [kN] (the decimal mark is '.')")


@pytest.mark.parametrize("space", ["", " "])
def test_text_that_looks_like_a_missing_value_passes_through(tmp_path, space):
    """pandas' words for a missing cell ('NA', 'None', 'NULL', 'nan' ...) make a number cell missing, but a text
    column keeps them as typed (an id 'NA', a note 'None'); an empty text cell is missing. pyarrow's reader and
    pandas' parser (a space after a separator) read alike."""
    path = tmp_path / "na.csv"
    path.write_text("id,designation,lubrication,n [rpm],Fr [kN],Fa [kN],nu [mm^2/s],comment,serial\n"
                    f"NA,{space}6208,oil_bath,1480,3.2,0.9,40,None,NULL\n"
                    "nan,6208,oil_bath,1480,NA,0.9,40,N/A,null\n"
                    ",6208,oil_bath,1480,3.2,,40,,\n")
    table = read_csv(path)
    assert table["id"].tolist()[:2] == ["NA", "nan"] and pd.isna(table["id"].iat[2])
    assert table["comment"].tolist()[:2] == ["None", "N/A"] and pd.isna(table["comment"].iat[2])
    assert table["serial"].tolist()[:2] == ["NULL", "null"]
    assert pd.isna(table["Fr [kN]"].iat[1]) and pd.isna(table["Fa [kN]"].iat[2])
    assert table["Fr [kN]"].dtype.kind == "f"


@pytest.mark.parametrize("space", ["", " "])
def test_lines_of_separators_only_are_no_rows(tmp_path, space):
    """Spreadsheets export rows they once used as ',,,,,,': skipped like blank lines, the rows after them still
    cited by their own line (pyarrow's reader and pandas' parser alike)."""
    path = tmp_path / "seps.csv"
    path.write_text("id,designation,lubrication,n [rpm],Fr [kN],Fa [kN],nu [mm^2/s]\n"
                    f"A,{space}6208,oil_bath,1480,3.2,0.9,40\n,,,,,,\nB,6208,oil_bath,1480,5,0.9,x\n,,,,,,\n")
    out = calc_csv(path)
    assert out["id"].tolist() == ["A", "B"]
    assert out["status"].tolist() == ["ok", "error"]
    assert out["message"].iat[1].startswith("row 4 (id \"B\"): 'x' is not a number for nu [mm^2/s]")


def test_a_separator_at_the_end_of_every_line_adds_no_column(tmp_path):
    path = tmp_path / "trailing.csv"
    path.write_text("id,designation,lubrication,n [rpm],Fr [kN],Fa [kN],nu [mm^2/s],\n"
                    "A,6208,oil_bath,1480,3.2,0.9,40,\nB,6208,oil_bath,1480,5,0.9,40,\n")
    assert list(read_csv(path).columns) == ["id", "designation", "lubrication", "n [rpm]", "Fr [kN]", "Fa [kN]",
                                            "nu [mm^2/s]"]


@pytest.mark.parametrize("encoding, opened_by_arrow", [("utf-8", True), ("utf-8-sig", False), ("cp1252", False)])
def test_pyarrow_reader_is_never_given_a_python_file(tmp_path, monkeypatch, encoding, opened_by_arrow):
    """pyarrow's threaded CSV reader may drop its source on one of its threads after read_csv returned; a Python
    file object freed there needs the GIL, and a process that is exiting then aborts (exit 134, 'terminate called
    without an active exception'). So the reader opens the file itself where its bytes are the text read, and
    reads an Arrow-owned copy where a byte-order mark was taken off or another encoding converted."""
    from bearingheat.io import csv_reader

    sources = []
    read = csv_reader.pa_csv.read_csv
    monkeypatch.setattr(csv_reader.pa_csv, "read_csv", lambda source, **options: (sources.append(source),
                                                                                  read(source, **options))[1])
    row = ["Lager vorn (Öl)" if encoding != "utf-8" else "front", *ROW[1:]]
    path = _write(tmp_path / "in.csv", ",", ".", rows=(row,), encoding=encoding)
    table = read_csv(path)
    assert table.loc[0, "id"] == row[0] and table.loc[0, "Fr [kN]"] == 2.5
    assert len(sources) == 1
    if opened_by_arrow:
        assert sources[0] == str(path)
    else:
        assert isinstance(sources[0], csv_reader.pa.BufferReader)


@pytest.mark.parametrize("cell", ["TRUE", "0x10"])
def test_a_number_column_with_a_logical_word_or_a_hexadecimal_number_is_read_as_pandas_reads_it(tmp_path, cell):
    """pyarrow's reader (the fast path) read a column of TRUE, 1, 0 as logical values (every row in error, the
    output showing True) and 0x10 as 16 (status ok), where pandas' parser reads 1 and 0 as numbers and neither
    TRUE nor 0x10 as one. Such files now go to pandas' parser: only the row of that cell is in error."""
    path = tmp_path / "in.csv"
    path.write_text("id,designation,d [mm],D [mm],C0 [kN],lubrication,n [rpm],Fr [kN],nu [mm^2/s]\n"
                    f"a,6208,40,80,18,oil_bath,1480,{cell},40\nb,6208,40,80,18,oil_bath,1480,1,40\n"
                    "c,6208,40,80,18,oil_bath,1480,0,40\n")
    result = calc_csv(path)
    assert result["Fr [kN]"].tolist() == [cell, "1", "0"]
    # (the 0 is a number: a load of 0, below the 6208's minimum load, a warning)
    assert result["status"].tolist() == ["error", "ok", "warning"]
    assert result["message"].iloc[0] == f"row 2 (id \"a\"): '{cell}' is not a number for Fr [kN]"
    assert main(["calc", str(path), "-o", str(tmp_path / "out.csv"), "-q"]) == 1
    assert (tmp_path / "out.csv").read_text().splitlines()[1].startswith(f"a,6208,40,80,18,oil_bath,1480,{cell},40,")


def test_times_dates_and_durations_are_written_as_to_csv_writes_them(tmp_path):
    """The CSV writer wrote a duration of 1 h as 3600000000 (its microseconds), dates as
    '2024-01-01 00:00:00.000000' and a time zone as '+0100'. They are now pandas' to_csv text, byte for byte."""
    import datetime

    frame = pd.DataFrame({
        "id": ["a", "b", "c"],
        "day": pd.to_datetime(["2024-01-01", None, "2024-03-01"]),
        "at": pd.to_datetime(["2024-01-01 00:00:00", None, "2024-03-01 12:30:00"]),
        "at_ms": pd.to_datetime(["2024-01-01 00:00:00.500", None, "2024-03-01 12:30:00.000"]),
        "installed": pd.date_range("2024-01-01", periods=3, tz="Europe/Berlin"),
        "runtime": pd.to_timedelta([3600, None, 90], unit="s"),
        "days": pd.to_timedelta([1, 2, None], unit="D"),
        "date": [datetime.date(2024, 1, 1), None, datetime.date(2024, 2, 29)],
        "time": [datetime.time(12, 30), None, datetime.time(1, 2, 3, 4)],
    })
    write_csv(frame, tmp_path / "out.csv")
    text = (tmp_path / "out.csv").read_text()
    assert text == frame.to_csv(index=False)
    assert text.splitlines()[1] == ("a,2024-01-01,2024-01-01 00:00:00,2024-01-01 00:00:00.500,"
                                    "2024-01-01 00:00:00+01:00,0 days 01:00:00,1 days,2024-01-01,12:30:00")
    write_csv(pa.Table.from_pandas(frame, preserve_index=False), tmp_path / "arrow.csv")
    assert (tmp_path / "arrow.csv").read_text() == text


@pytest.mark.parametrize("source_suffix, output_suffix", [(".csv", ".csv"), (".csv", ".xlsx"), (".parquet", ".csv"),
                                                          (".parquet", ".xlsx"), (".parquet", ".parquet")])
def test_a_header_calc_cannot_read_passes_through_every_output(tmp_path, source_suffix, output_suffix):
    """A column whose brackets are no unit ('remark [see note]]') passed through to a CSV but was refused with
    -o OUT.xlsx from a Parquet file (and by --dask): every output now passes it through, in its place."""
    table = pd.read_csv(EXAMPLE_CSV)
    table.insert(3, "remark [see note]]", [f"r{i}" for i in range(len(table))])
    source = tmp_path / f"in{source_suffix}"
    table.to_csv(source, index=False) if source_suffix == ".csv" else table.to_parquet(source, index=False)
    out = tmp_path / f"out{output_suffix}"
    assert main(["calc", str(source), "-o", str(out), "-q"]) == 0
    if output_suffix == ".xlsx":  # a header row of names, a row of units below it
        written = pd.read_excel(out, sheet_name="Results", skiprows=[1])
    else:
        written = pd.read_csv(out) if output_suffix == ".csv" else pd.read_parquet(out)
    assert list(written.columns).index("remark [see note]]") == 3
    assert written["remark [see note]]"].tolist() == ["r0", "r1", "r2", "r3", "r4", "r5"]
    assert written["status"].tolist() == calc_csv(EXAMPLE_CSV)["status"].tolist()


@pytest.mark.parametrize("sep, file_sep, option, described", [(";", ",", ",", "comma ','"),
                                                               ("tab", ";", ";", "semicolon ';'")])
def test_a_separator_the_header_lacks_is_named(tmp_path, capsys, sep, file_sep, option, described):
    """--sep that leaves the header one column was refused for the table's first missing column ('missing column:
    n [1/min]'), which named no cause; it now says which separator the file uses."""
    path = _write(tmp_path / "in.csv", file_sep)
    assert main(["calc", str(path), "--sep", sep]) == 2
    header = file_sep.join(HEAD)
    shown = header[:40] + "..."
    assert capsys.readouterr().err == (
        f"bearingheat calc: error: {path}: --sep '{'tab' if sep == 'tab' else sep}' leaves the header one column "
        f"({shown!r}); its cells are separated by {described}: give --sep '{option}' or leave --sep out\n")


@pytest.mark.parametrize("raw, sep, found", [
    (b"id,n\npump 0x1F,3\n", ",", False),     # inside a text cell: no number, the file stays on pyarrow's reader
    (b"id,n\na,0x10\n", ",", True), (b'id;n\na; "0X1"\n', ";", True), (b"n\n0x1\n", ",", True),
    (b"id,n\na,-0x1\n", ",", True), (b"id\tn\na\t0x1\n", "\t", True)])
def test_only_a_cell_that_begins_with_0x_is_a_hexadecimal_number(raw, sep, found):
    from bearingheat.io.csv_reader import _holds_a_hexadecimal_cell

    assert _holds_a_hexadecimal_cell(raw, sep) is found


def test_a_column_named_like_a_result_is_refused(tmp_path, capsys):
    """A designer's 'status' (released/draft) was replaced in the output by calc's ok/error."""
    table = pd.read_csv(EXAMPLE_CSV)
    table["status"] = "released"
    table.to_csv(tmp_path / "own.csv", index=False)
    message = "column 'status' is a column calc writes; rename it (e.g. 'status (design)')"
    with pytest.raises(InputError, match=f"^{re.escape(message)}$"):
        calc_csv(tmp_path / "own.csv")
    assert main(["calc", str(tmp_path / "own.csv"), "-o", str(tmp_path / "out.csv")]) == 2
    assert message in capsys.readouterr().err and not (tmp_path / "out.csv").exists()
    table = table.drop(columns="status").assign(**{"MR [N*mm]": 999.0})
    table.to_parquet(tmp_path / "own.parquet")
    with pytest.raises(InputError, match=re.escape("column 'MR [N*mm]' is a column calc writes; rename it "
                                                   "(e.g. 'MR (design)')")):
        calc_csv(tmp_path / "own.parquet")
    # the Python API refuses it alike (the check is calc's own)
    with pytest.raises(InputError, match=re.escape("column 'MR [N*mm]' is a column calc writes")):
        bh.calc(table)


def test_a_results_table_of_calc_is_computed_again(tmp_path):
    """calc's own output read back: its status holds only ok/warning/error, its result columns are calc's."""
    write_csv(csv_result(), tmp_path / "results.csv")
    again = calc_csv(tmp_path / "results.csv")
    expected = csv_result()
    pd.testing.assert_series_equal(again["MR [N*mm]"], expected["MR [N*mm]"], rtol=1e-12)
    assert again["status"].tolist() == expected["status"].tolist()
