"""CSV tables of supports: read one for calc, write its results.

A CSV of supports has one header row of ``name [unit]`` columns (the column
contract, :mod:`bearingheat.calc.contract`) and one row per support. Spaces
after the separators are ignored.

The separator and the decimal mark are found from the file, as a
spreadsheet program saves it: the header's most frequent separator among
``,``, ``;`` and tab is the separator; with ``;`` or tab, numbers written
with a decimal comma (``1,5``) are read as such when no number in the file
has a decimal point. ``sep`` and ``decimal`` set them explicitly.

Text the spreadsheet would turn into a formula (a cell starting with ``=``,
``+``, ``-``, ``@``, tab or carriage return, the OWASP rule for CSV
injection) is written with a leading apostrophe by :func:`write_csv`;
numbers such as ``-3.2`` stay numbers.

>>> import io
>>> text = "id;d [mm];n [1/min]\\nspindle rear;40;1500,5\\n"
>>> sniff_format(text)
(';', ',')
>>> escape_formulas(pd.DataFrame({"note": ["=1+1", "-3.2", "ok"], "x": [-1.0, 2.0, 3.0]}))["note"].tolist()
["'=1+1", '-3.2', 'ok']
"""
from __future__ import annotations

import codecs
import csv
import io
import re
from pathlib import Path

import pandas as pd

from bearingheat.calc.contract import columns as contract_columns
from bearingheat.calc.contract import input_units, parse_header
from bearingheat.calc.table import calc
from bearingheat.errors import InputError
from bearingheat.io.arrow import ARROW_SUFFIXES, read_arrow, write_arrow
from bearingheat.io.files import atomic_write

__all__ = ["read_csv", "read_table", "read_text", "write_csv", "sniff_format", "escape_formulas", "escape_cell", "calc_csv",
           "cite_rows", "separator", "SEPARATORS", "TABLE_WRITERS", "write_table", "check_table_suffix"]

#: separator -> how a message names it (and how --sep accepts it)
SEPARATORS = {",": "comma ','", ";": "semicolon ';'", "\t": "tab"}
_FORMULA_START = ("=", "+", "-", "@", "\t", "\r")
_NUMBER = re.compile(r"^\s*[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?\s*$")
_COMMA_NUMBER = re.compile(r"^\s*[+-]?\d*,\d+([eE][+-]?\d+)?\s*$")
_POINT_NUMBER = re.compile(r"^\s*[+-]?\d*\.\d+([eE][+-]?\d+)?\s*$")
_QUOTED = re.compile(r'"[^"]*"')
#: lines looked at to tell a decimal comma from a decimal point
_SNIFF_LINES = 2000


def _decode(raw: bytes, path: Path) -> str:
    """The text of a CSV file: UTF-8 (with or without BOM), UTF-16 with BOM, or Windows-1252."""
    if raw.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)):
        return raw.decode("utf-16")
    if b"\x00" in raw:
        raise InputError(f"{path}: not a CSV text file (it holds binary data; is it a workbook with the wrong name?)")
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        try:
            return raw.decode("cp1252")
        except UnicodeDecodeError:
            raise InputError(f"{path}: not a readable CSV (byte 0x{raw[exc.start]:02x} at position {exc.start} is "
                             "not UTF-8 text); save it as 'CSV UTF-8'") from exc


def read_text(path) -> str:
    """The text of a CSV file (UTF-8 with or without BOM, UTF-16 with BOM, or Windows-1252); :class:`InputError`
    for a binary file or an empty one."""
    path = Path(path)
    with open(path, "rb") as handle:
        raw = handle.read()
    text = _decode(raw, path)
    if not text.strip():
        raise InputError(f"{path}: not a readable CSV (the file is empty)")
    return text


def _first_line(text: str) -> str:
    for line in io.StringIO(text, newline=""):
        if line.strip():
            return line
    return ""


def sniff_format(text: str, sep: str | None = None) -> tuple[str, str]:
    """(separator, decimal mark) of a CSV text (the decimal mark only, when ``sep`` is given).

    The separator is the most frequent of ``,``, ``;`` and tab in the header
    line (outside quotes; comma on a tie or when there is none). The decimal
    mark is ``,`` when the separator is not a comma, some cell is a number
    with a decimal comma and none has a decimal point; else ``.``.
    """
    if sep is None:
        header = _QUOTED.sub("", _first_line(text))
        counts = {s: header.count(s) for s in SEPARATORS}
        sep = max(SEPARATORS, key=lambda s: (counts[s], s == ","))
    if sep == ",":
        return sep, "."
    comma = point = 0
    for number, row in enumerate(csv.reader(io.StringIO(text, newline=""), delimiter=sep)):
        if number > _SNIFF_LINES:
            break
        for cell in row:
            comma += bool(_COMMA_NUMBER.match(cell))
            point += bool(_POINT_NUMBER.match(cell))
    return sep, ("," if comma and not point else ".")


def separator(sep: str | None) -> str | None:
    """``--sep`` text to the separator: ',', ';', 'tab' (or a tab, or backslash-t)."""
    if sep is None:
        return None
    text = {"tab": "\t", "\\t": "\t", "TAB": "\t"}.get(sep, sep)
    if text not in SEPARATORS:
        raise InputError(f"--sep {sep!r}: give ',', ';' or tab")
    return text


def _records(text: str, sep: str) -> tuple[list[str], list[int]]:
    """The raw header cells and the file line number of each data row (blank lines skipped, as pandas does)."""
    header: list[str] | None = None
    lines: list[int] = []
    reader = csv.reader(io.StringIO(text, newline=""), delimiter=sep, skipinitialspace=True)
    end = 0
    for record in reader:
        start, end = end + 1, reader.line_num
        if not record or (len(record) == 1 and not record[0].strip()):
            continue
        if header is None:
            header = [cell.lstrip() for cell in record]
        else:
            lines.append(start)
    return header or [], lines


def _duplicates(path: Path, header: list[str]) -> None:
    seen: dict[str, int] = {}
    for position, name in enumerate(header, start=1):
        name = name.strip()
        if not name:
            continue
        if name in seen:
            raise InputError(f"{path}: column {name!r} appears twice (columns {seen[name]} and {position}); "
                             "keep one")
        seen[name] = position


def _parser_message(exc: Exception) -> str:
    text = str(exc).strip().splitlines()[0] if str(exc).strip() else type(exc).__name__
    match = re.search(r"Expected (\d+) fields in line (\d+), saw (\d+)", text)
    if match:
        expected, line, saw = match.groups()
        return f"line {line} has {saw} fields, the header {expected}"
    return text


def _text_columns(header: list[str]) -> list[str]:
    """Headers read as text: no contract column (so that they pass through untouched, '007' stays '007'), or a
    contract column of text (id, designation, lubrication ...)."""
    known = set(contract_columns()) | set(contract_columns(kind="output"))
    text = {name for name, unit in input_units().items() if unit == ""}
    names = {h: parse_header(h, strict=False)[0] for h in header if h}
    return [h for h, name in names.items() if name not in known or name in text]


def _read_text(path: Path, *, sep: str | None, decimal: str | None, what: str) -> pd.DataFrame:
    """Parse a CSV file into a DataFrame; ``attrs['lines']`` holds the file line number of each row."""
    sep = separator(sep)
    if decimal not in (None, ".", ","):
        raise InputError(f"--decimal {decimal!r}: give '.' or ','")
    text = read_text(path)
    sep, found_decimal = sniff_format(text, sep)
    decimal = decimal or found_decimal
    if sep == decimal:
        raise InputError(f"--decimal {decimal!r} is also the separator; give --sep ';' or --sep tab with it")
    header, lines = _records(text, sep)
    _duplicates(path, header)
    try:
        table = pd.read_csv(io.StringIO(text), sep=sep, decimal=decimal, skipinitialspace=True,
                            dtype={h: str for h in _text_columns(header)})
    except (pd.errors.ParserError, pd.errors.EmptyDataError, ValueError) as exc:
        raise InputError(f"{path}: not a readable CSV ({_parser_message(exc)}); its columns were read as "
                         f"separated by {SEPARATORS[sep]} with decimal mark {decimal!r}: if the file uses "
                         "another separator or decimal commas, give --sep (',', ';' or tab) and --decimal "
                         "(',' or '.')") from exc
    if len(table) == 0:
        raise InputError(f"{path}: no {what} (only a header row)")
    table.attrs["lines"] = lines if len(lines) == len(table) else None
    table.attrs["source"] = str(path)
    return table


def read_csv(path, *, sep: str | None = None, decimal: str | None = None) -> pd.DataFrame:
    """The table of a CSV file of supports; :class:`InputError` when it is not a readable CSV (the message
    names the file and the cause).

    The separator and decimal mark are found from the file unless given
    (:func:`sniff_format`); a column named twice is refused by its name;
    columns the contract does not know are read as text and passed through
    untouched. ``attrs['lines']`` holds the file line number of each row
    (the header is line 1), for :func:`cite_rows`.
    """
    return _read_text(Path(path), sep=sep, decimal=decimal, what="supports")


def read_table(path, sheet: str | None = None, *, sep: str | None = None, decimal: str | None = None
               ) -> pd.DataFrame:
    """A CSV or xlsx file of measurements or readings as a DataFrame (first sheet unless ``sheet``).

    A missing or unreadable file raises :class:`InputError` naming it; a CSV
    is read as :func:`read_csv` reads it.
    """
    path = Path(path)
    if not path.is_file():
        raise InputError(f"{path}: no such file")
    if sheet and path.suffix.lower() not in (".xlsx", ".xlsm"):
        raise InputError("--sheet applies to Excel workbooks only")
    if path.suffix.lower() in ARROW_SUFFIXES:
        return read_arrow(path)
    if path.suffix.lower() not in (".xlsx", ".xlsm"):
        return _read_text(path, sep=sep, decimal=decimal, what="rows")
    try:
        table = pd.read_excel(path, sheet_name=sheet or 0)
    except ValueError as exc:  # a missing sheet, an unreadable cell
        raise InputError(f"{path}: not a readable table ({exc})") from exc
    if len(table) == 0:
        raise InputError(f"{path}: no rows (only a header row)")
    return table


def cite_rows(result: pd.DataFrame, lines: list[int] | None) -> pd.DataFrame:
    """Begin each row message with where the row is in the file: ``row 7 (id "spindle rear"): ...``.

    ``lines`` are the file line numbers of the rows (``read_csv(...).attrs['lines']``); rows without a
    message are left as they are. Returns ``result`` (changed in place).
    """
    if lines is None or "message" not in result.columns or len(lines) != len(result):
        return result
    ids = result["id"] if "id" in result.columns else None
    messages = result["message"].tolist()
    for position, message in enumerate(messages):
        if not isinstance(message, str) or not message:
            continue
        who = ids.iat[position] if ids is not None else None
        label = f' (id "{str(who).strip()}")' if isinstance(who, str) and who.strip() else ""
        messages[position] = f"row {lines[position]}{label}: {message}"
    result["message"] = messages
    return result


def _set_aside(table: pd.DataFrame) -> tuple[pd.DataFrame, list[tuple[int, str, pd.Series]]]:
    """Columns whose header calc cannot read (brackets that are no ``name [unit]``), taken out to be put back."""
    extras = []
    for position, header in enumerate(table.columns):
        try:
            parse_header(header)
        except InputError:
            extras.append((position, header, table[header]))
    if extras:
        table = table.drop(columns=[header for _, header, _ in extras])
    return table, extras


def calc_csv(path, *, sep: str | None = None, decimal: str | None = None, **options) -> pd.DataFrame:
    """:func:`bearingheat.calc.table.calc` on a CSV file of supports, its row messages citing the file's rows
    (or on a Parquet or Arrow/Feather file, by its suffix).

    Columns the contract does not know are passed through untouched, even
    with brackets that are no unit in their names; ``options`` go to calc.
    """
    if Path(path).suffix.lower() in ARROW_SUFFIXES:  # a binary table: no separators, no file lines to cite
        return calc(read_arrow(path), **options)
    table = read_csv(path, sep=sep, decimal=decimal)
    lines = table.attrs.get("lines")
    usable, extras = _set_aside(table)
    result = calc(usable, **options)
    for position, header, values in extras:
        result.insert(position, header, values.to_numpy())
    return cite_rows(result, lines)


def escape_cell(value):
    """``value`` with a leading apostrophe when it is text a spreadsheet would read as a formula."""
    if isinstance(value, str) and value.startswith(_FORMULA_START) and not _NUMBER.match(value):
        return "'" + value
    return value


def escape_formulas(frame: pd.DataFrame) -> pd.DataFrame:
    """A copy of ``frame`` whose text cells and headers are escaped by :func:`escape_cell` (numbers untouched)."""
    out = frame.copy()
    for column in out.columns:
        if not (pd.api.types.is_numeric_dtype(out[column].dtype) or pd.api.types.is_bool_dtype(out[column].dtype)):
            out[column] = out[column].map(escape_cell)
    out.columns = [escape_cell(c) for c in out.columns]
    return out


def write_csv(result: pd.DataFrame, path, *, escape: bool = True) -> Path:
    """Write calc results as a CSV (headers ``name [unit]``, no index column), atomically.

    Text cells that would be formulas in a spreadsheet are escaped
    (:func:`escape_formulas`) unless ``escape=False``. The file is replaced
    atomically (:func:`bearingheat.io.files.atomic_write`): a failure leaves
    the old file. Returns the file written (the real file when ``path`` is a
    symbolic link).
    """
    frame = escape_formulas(result) if escape else result
    return atomic_write(path, lambda temp: frame.to_csv(temp, index=False))


#: output suffix -> writer(result, path, escape) of the table formats (workbooks are written by io.excel)
TABLE_WRITERS = {
    ".csv": lambda result, path, escape: write_csv(result, path, escape=escape),
    **{suffix: (lambda result, path, escape: write_arrow(result, path)) for suffix in ARROW_SUFFIXES},
}


def check_table_suffix(path, also: tuple[str, ...] = ()) -> None:
    """Raise :class:`InputError` when ``path`` has no suffix of :data:`TABLE_WRITERS` (or of ``also``)."""
    suffix = Path(path).suffix.lower()
    accepted = (*TABLE_WRITERS, *also)
    if suffix not in accepted:
        raise InputError(f"{path}: cannot write a {suffix or 'file without suffix'}; the output formats are "
                         f"{', '.join(accepted)}")


def write_table(result: pd.DataFrame, path, *, escape: bool = True) -> Path:
    """Write a results table in the format of the suffix of ``path`` (:data:`TABLE_WRITERS`), atomically.

    ``escape`` applies to CSV (:func:`write_csv`); Parquet and Arrow hold text as text.
    """
    check_table_suffix(path)
    return TABLE_WRITERS[Path(path).suffix.lower()](result, path, escape)
