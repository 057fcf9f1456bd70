"""Reading a CSV table of supports: its encoding, separator, decimal mark, row lines and cells.

A CSV of supports has one header row of ``name [unit]`` columns (the column
contract, :mod:`bearingheat.calc.contract`) and one row per support. Spaces
after the separators are ignored.

The separator and the decimal mark are found from the file, as a
spreadsheet program saves it: the header's most frequent separator among
``,``, ``;`` and tab is the separator; with ``;`` or tab, numbers written
with a decimal comma (``1,5``) are read as such when no number in the file
has a decimal point (:func:`sniff_format`).

The cells are read by pyarrow's multi-threaded CSV reader where it gives
pandas' result (10^6 rows in about half a second on two cores), else by pandas' own parser: when a
cell begins with white space (pandas skips it), a header cell is blank, a
column would be read as dates or as logical values (pyarrow reads ``1`` and
``0`` as true and false beside ``TRUE``), or a column of whole numbers may hold
a hexadecimal one (pyarrow reads ``0x10`` as 16; pandas and calc as no
number). The file line of each row is found in arrays when no cell is quoted
(no cell can then span lines), else with Python's csv module. Neither path
holds more than the file's bytes, its table and (for the pandas path) its text
at once.

>>> text = "id;d [mm];n [1/min]\\nspindle rear;40;1500,5\\n"
>>> sniff_format(text)
(';', ',')
"""
from __future__ import annotations

import codecs
import csv
import io
import re
from pathlib import Path
from typing import NamedTuple

import numpy as np
import pandas as pd
import pyarrow as pa
import pyarrow.compute as pc
import pyarrow.csv as pa_csv

from bearingheat.calc.contract import columns as contract_columns
from bearingheat.calc.contract import input_units, parse_header
from bearingheat.errors import InputError
from bearingheat.io.units_row import NO_UNIT, looks_like_units_row, unit_contradicts_header

__all__ = ["SEPARATORS", "CsvSource", "RowLines", "read_text", "sniff_format", "separator", "read_source",
           "refuse_duplicate_columns"]

#: separator -> how a message names it (and how --sep accepts it)
SEPARATORS = {",": "comma ','", ";": "semicolon ';'", "\t": "tab"}
_COMMA_NUMBER = re.compile(r"^\s*[+-]?\d*,\d+([eE][+-]?\d+)?\s*$")
_POINT_NUMBER = re.compile(r"^\s*[+-]?\d*\.\d+([eE][+-]?\d+)?\s*$")
_QUOTED = re.compile(r'"[^"]*"')
_QUOTED_BYTES = re.compile(rb'"[^"]*"')
#: lines looked at to tell a decimal comma from a decimal point
_SNIFF_LINES = 2000
#: ASCII white space: a line of only these (the separator aside) is blank, as csv.reader and pandas skip it
_WHITE_SPACE = frozenset(b" \t\r\x0b\x0c")
#: pandas' words for a missing cell (pandas.read_csv's default na_values), for pyarrow's reader
_MISSING = ["", "#N/A", "#N/A N/A", "#NA", "-1.#IND", "-1.#QNAN", "-NaN", "-nan", "1.#IND", "1.#QNAN", "<NA>", "N/A",
            "NA", "NULL", "NaN", "None", "n/a", "nan", "null"]
#: Arrow types pyarrow may give a column that is not text (else the file goes to pandas' parser). Not logical
#: values: pyarrow reads 1 and 0 as true and false where TRUE is in the column, pandas reads them as numbers
_ARROW_KINDS = (pa.types.is_integer, pa.types.is_floating, pa.types.is_null, pa.types.is_string,
                pa.types.is_large_string)
#: bytes decoded at a time to check that a file is UTF-8
_CHECK_BYTES = 1 << 24
#: bytes scanned at a time for line breaks and spaces
_SCAN_BYTES = 1 << 20


def _utf8(raw: bytes) -> bool:
    """True when ``raw`` is UTF-8 text (checked a slice at a time, without holding the whole text)."""
    if raw.isascii():  # ASCII is UTF-8, and this test is five times as fast as decoding
        return True
    decoder = codecs.getincrementaldecoder("utf-8")()
    view = memoryview(raw)
    try:
        for start in range(0, len(raw), _CHECK_BYTES):
            decoder.decode(view[start:start + _CHECK_BYTES])
        decoder.decode(b"", final=True)
    except UnicodeDecodeError:
        return False
    return True


def _utf8_bytes(raw: bytes, path: Path) -> bytes:
    """The bytes of a CSV file as UTF-8 without BOM (from UTF-8 with or without BOM, UTF-16 with BOM, or
    Windows-1252); :class:`InputError` for a binary file or an empty one."""
    if raw.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)):
        raw = raw.decode("utf-16").encode("utf-8")
    elif b"\x00" in raw:
        raise InputError(f"{path}: not a CSV text file (it holds binary data; is it a workbook with the wrong name?)")
    elif raw.startswith(codecs.BOM_UTF8):
        raw = raw[len(codecs.BOM_UTF8):]
    if not _utf8(raw):
        try:
            raw = raw.decode("cp1252").encode("utf-8")
        except UnicodeDecodeError as exc:
            raise InputError(f"{path}: not a readable CSV (byte 0x{raw[exc.start]:02x} at position {exc.start} "
                             "is not UTF-8 text); save it as 'CSV UTF-8'") from exc
    if not raw or raw.isspace():  # (no stripped copy of a big file)
        raise InputError(f"{path}: not a readable CSV (the file is empty)")
    return raw


def read_text(path) -> str:
    """The text of a CSV file (UTF-8 with or without BOM, UTF-16 with BOM, or Windows-1252); :class:`InputError`
    for a binary file or an empty one."""
    path = Path(path)
    return _utf8_bytes(path.read_bytes(), path).decode("utf-8")


def _first_line(text: str) -> str:
    """The first line that is not blank (looked for in the first 64 kB, then in the whole text)."""
    for size in (1 << 16, len(text)):
        for line in io.StringIO(text[:size], newline=""):
            if line.strip() and (size >= len(text) or line.endswith(("\n", "\r"))):
                return line
        if size >= len(text):
            break
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


def _sniffed_text(raw: bytes) -> str:
    """The text :func:`sniff_format` needs: the first lines of an unquoted file, else all of it."""
    end = -1
    for _ in range(_SNIFF_LINES + 3):
        end = raw.find(b"\n", end + 1)
        if end < 0:
            return raw.decode("utf-8")
    head = raw[:end + 1]
    return raw.decode("utf-8") if b'"' in head else head.decode("utf-8")


def separator(sep: str | None) -> str | None:
    """``--sep`` text to the separator: ',', ';', 'tab' (or a tab, or backslash-t)."""
    if sep is None:
        return None
    text = {"tab": "\t", "\\t": "\t", "TAB": "\t"}.get(sep, sep)
    if text not in SEPARATORS:
        raise InputError(f"--sep {sep!r}: give ',', ';' or tab")
    return text


def _quoted_records(text: str, sep: str) -> tuple[list[str], list[int]]:
    """The raw header cells and the file line number of each data row, by Python's csv module (quoted cells
    may span lines; blank lines skipped, as pandas does)."""
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


def _positions(data: np.ndarray, byte: int) -> np.ndarray:
    """The positions of ``byte`` in ``data``, found a slice of :data:`_SCAN_BYTES` at a time (the mask of a slice
    stays in the processor's cache: 0.06 s for 120 MB, 0.2 s in one piece)."""
    parts = [np.flatnonzero(data[start:start + _SCAN_BYTES] == byte) + start
             for start in range(0, len(data), _SCAN_BYTES)]
    return np.concatenate(parts) if parts else np.zeros(0, dtype=np.intp)


def _unquoted_records(raw: bytes, sep: str) -> tuple[list[str], np.ndarray]:
    """:func:`_quoted_records` of a UTF-8 text without quotes (so without line breaks inside cells), in arrays:
    10^6 lines in a fraction of a second."""
    data = np.frombuffer(raw, dtype=np.uint8)
    ends = _positions(data, ord("\n"))
    if len(data) and data[-1] != ord("\n"):
        ends = np.append(ends, len(data))
    if len(ends) == 0:
        return [], np.zeros(0, dtype=np.int64)
    starts = np.concatenate(([0], ends[:-1] + 1))
    white = np.zeros(256, dtype=bool)
    white[list(_WHITE_SPACE - {ord(sep)})] = True
    # a line is filled when its first byte is no white space; only the others are looked at one by one
    filled = (ends > starts) & ~white[data[np.minimum(starts, len(data) - 1)]]
    for line in np.flatnonzero(~filled & (ends > starts)):
        filled[line] = not white[data[starts[line]:ends[line]]].all()
    numbers = np.flatnonzero(filled) + 1
    if len(numbers) == 0:
        return [], np.zeros(0, dtype=np.int64)
    line = numbers[0] - 1
    first = raw[starts[line]:ends[line]].decode("utf-8")
    header = [cell.lstrip() for cell in first.rstrip("\r").split(sep)]
    return header, numbers[1:]


def _records(raw: bytes, sep: str, text: str | None = None) -> tuple[list[str], list[int] | np.ndarray]:
    """The raw header cells and the file line number of each data row (blank lines skipped, as pandas does)."""
    # no quoted cells: a row is a line (one byte is looked for at memchr speed; counting pairs takes 0.1 s)
    if b'"' not in raw and (b"\r" not in raw or raw.count(b"\r") == raw.count(b"\r\n")):
        return _unquoted_records(raw, sep)
    return _quoted_records(text if text is not None else raw.decode("utf-8"), sep)


class RowLines:
    """The file line number of each row of a table read from a CSV (``read_csv(...).attrs['lines']``).

    Kept in ``DataFrame.attrs``, which pandas deep-copies on every operation
    on the frame: this holder gives itself as its deep copy, so that a table
    of 10^6 rows does not copy 10^6 numbers hundreds of times through calc
    (measured: 29 s of a 35 s run on 2*10^5 rows before). It is read-only;
    a slice is the lines of a block of rows.
    """

    __slots__ = ("_numbers",)

    def __init__(self, numbers):
        self._numbers = np.array(numbers, dtype=np.int64)
        self._numbers.setflags(write=False)

    def __deepcopy__(self, memo):
        return self

    def __len__(self) -> int:
        return len(self._numbers)

    def __getitem__(self, position):
        if isinstance(position, slice):
            return RowLines(self._numbers[position])
        return int(self._numbers[position])

    def __iter__(self):
        return iter(self._numbers.tolist())

    def __eq__(self, other) -> bool:  # pandas compares attrs when it concatenates frames
        return isinstance(other, RowLines) and np.array_equal(self._numbers, other._numbers)

    def __hash__(self) -> int:
        return hash((len(self._numbers), self._numbers[:8].tobytes()))

    def __repr__(self) -> str:
        return f"RowLines({len(self)} rows)"


def refuse_duplicate_columns(path: Path, header: list[str]) -> None:
    """:class:`InputError` for a column name that appears twice in a file's header (blank names aside)."""
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


def _holds_a_hexadecimal_cell(raw: bytes, sep: str) -> bool:
    """Whether a cell of the CSV bytes ``raw`` begins with 0x (after spaces, a quote or a sign): a hexadecimal
    number pyarrow would read; '0x' inside a text cell ('pump 0x1F') is none."""
    if b"0x" not in raw and b"0X" not in raw:  # (no pattern search in the common case)
        return False
    cell_start = rb"(?:^|" + re.escape(sep.encode()) + rb')[ \t]*"?[ \t]*[+-]?0[xX]'
    return re.search(cell_start, raw, flags=re.MULTILINE) is not None


def _arrow_source(raw: bytes, file: Path | None) -> str | pa.BufferReader:
    """What pyarrow's threaded CSV reader reads ``raw`` from: the file that holds it (opened by Arrow, read in
    blocks), else a copy in Arrow's own memory; never a Python object. The reader may drop its last reference to
    its source on one of its threads after read_csv has returned; a Python object there (a BytesIO) needs the GIL
    to be freed, and in a process that is exiting that thread is stopped inside a C++ destructor: std::terminate,
    'terminate called without an active exception', exit 134 (seen in about 1 of 40 short runs on a loaded
    machine; core dump: PyReadableFile's destructor on an Arrow worker thread)."""
    if file is not None:
        return str(file)
    stream = pa.BufferOutputStream()
    stream.write(raw)
    return pa.BufferReader(stream.getvalue())


def _space_after_separator(raw: bytes, sep: str) -> bool:
    """True when a cell of the CSV text ``raw`` begins with a space or tab (outside quotes): pandas skips it
    (``skipinitialspace``), pyarrow would keep it."""
    if b'"' in raw:
        raw = _QUOTED_BYTES.sub(b'""', raw)
    data = np.frombuffer(raw, dtype=np.uint8)
    if len(data) and data[0] in (ord(" "), ord("\t")):
        return True
    for start in range(1, len(data), _SCAN_BYTES):  # a slice at a time: no arrays the size of the file
        part = data[start:start + _SCAN_BYTES]
        spaces = np.flatnonzero((part == ord(" ")) | ((part == ord("\t")) if sep != "\t" else False)) + start
        before = data[spaces - 1]
        if ((before == ord(sep)) | (before == ord("\n")) | (before == ord("\r"))).any():
            return True
    return False


def _read_with_pyarrow(raw: bytes, sep: str, decimal: str, header: list[str], text_columns: list[str],
                       file: Path | None = None) -> pa.Table | None:
    """The Arrow table pyarrow's CSV reader makes of the UTF-8 bytes ``raw`` with pandas' conventions (its
    missing-value words, text columns as text, a column left blank as numbers), or None when the file needs
    pandas' parser for the same result: white space at the start of a cell, a blank header cell, a row pyarrow
    cannot split, a column it reads as something other than numbers or text (dates, logical values), or whole
    numbers in a file that holds '0x' (hexadecimal numbers pandas does not read). ``file``: the file that holds
    exactly ``raw``, for the reader to open itself."""
    if not all(h.strip() for h in header) or _space_after_separator(raw, sep):
        return None
    # pandas' missing-value words make number cells missing; a text column keeps them as typed ('NA', 'None'
    # are an id or a note), only its empty cells are missing
    options = dict(read_options=pa_csv.ReadOptions(autogenerate_column_names=False),
                   parse_options=pa_csv.ParseOptions(delimiter=sep, quote_char='"', ignore_empty_lines=True),
                   convert_options=pa_csv.ConvertOptions(null_values=_MISSING, strings_can_be_null=False,
                                                         decimal_point=decimal,
                                                         column_types={h: pa.large_string() for h in text_columns}))
    try:
        table = pa_csv.read_csv(_arrow_source(raw, file), **options)
    except (pa.ArrowInvalid, pa.ArrowNotImplementedError):
        return None
    pa.default_memory_pool().release_unused()  # the reader's freed buffers, back to the system
    if table.column_names != header:
        return None
    hexadecimal = None
    for i, field in enumerate(table.schema):
        if not any(kind(field.type) for kind in _ARROW_KINDS):
            return None
        if pa.types.is_integer(field.type):  # pyarrow reads 0x10 as 16; pandas (and calc) as no number
            hexadecimal = _holds_a_hexadecimal_cell(raw, sep) if hexadecimal is None else hexadecimal
            if hexadecimal:
                return None
        if pa.types.is_string(field.type) or pa.types.is_large_string(field.type):  # an empty text cell: missing
            column = table.column(i)
            table = table.set_column(i, field, pc.if_else(pc.equal(column, ""), pa.scalar(None, field.type), column))
        if pa.types.is_null(field.type):  # a column left blank: numbers, as pandas reads it
            table = table.set_column(i, field.with_type(pa.float64()), table.column(i).cast(pa.float64()))
    return table


def _read_with_pandas(text: str, path: Path, sep: str, decimal: str, header: list[str], text_columns: list[str]
                      ) -> pd.DataFrame:
    numbers = {name for h in header if h not in text_columns for name in (h, h.strip())}
    try:
        # the missing-value words for number columns only; a text column keeps 'NA', 'None' as typed
        table = pd.read_csv(io.StringIO(text), sep=sep, decimal=decimal, skipinitialspace=True,
                            dtype={h: str for h in text_columns}, keep_default_na=False,
                            na_values={name: _MISSING for name in numbers})
    except (pd.errors.ParserError, pd.errors.EmptyDataError, ValueError) as exc:
        raise InputError(f"{path}: not a readable CSV ({_parser_message(exc)}); its columns were read as "
                         f"separated by {SEPARATORS[sep]} with decimal mark {decimal!r}: if the file uses "
                         "another separator or decimal commas, give --sep (',', ';' or tab) and --decimal "
                         "(',' or '.')") from exc
    for name in table.columns:
        if name not in numbers:  # a text column: an empty cell is missing
            table[name] = table[name].mask(table[name] == "")
    return table


class CsvSource:
    """A CSV file read: ``table`` (an Arrow table from pyarrow's reader, or a DataFrame from pandas' parser),
    ``lines``, the file line of each row (None when they cannot be told), and the file's ``decimal`` mark (for
    the numbers the readers left as text: calc reads them with it)."""

    def __init__(self, table: pa.Table | pd.DataFrame, lines: RowLines | None, decimal: str = "."):
        self.table, self.lines, self.decimal = table, lines, decimal

    def __len__(self) -> int:
        return self.table.num_rows if isinstance(self.table, pa.Table) else len(self.table)


def read_source(path, *, sep: str | None = None, decimal: str | None = None, what: str = "supports") -> CsvSource:
    """Read a CSV file (:class:`CsvSource`); :class:`InputError` when it is not a readable CSV (the message names
    the file and the cause), names a column twice or has no rows."""
    path = Path(path)
    sep = given_sep = separator(sep)
    if decimal not in (None, ".", ","):
        raise InputError(f"--decimal {decimal!r}: give '.' or ','")
    as_read = path.read_bytes()
    raw = _utf8_bytes(as_read, path)
    unchanged = raw is as_read  # no byte-order mark taken off, no other encoding converted: pyarrow opens the file
    del as_read
    sep, found_decimal = sniff_format(_sniffed_text(raw), sep)
    decimal = decimal or found_decimal
    if sep == decimal:
        raise InputError(f"--decimal {decimal!r} is also the separator; give --sep ';' or --sep tab with it")
    header, lines = _records(raw, sep)
    if given_sep is not None and len(header) == 1:
        _refuse_a_separator_the_header_lacks(path, given_sep, header[0])
    refuse_duplicate_columns(path, header)
    units = _units_row(path, raw, sep, header, lines)
    if units is not None:  # the units row is no row of data: the readers get the file without it
        start, end = units.span
        raw, unchanged, lines = raw[:start] + raw[end:], False, lines[1:]
    text_columns = _text_columns(header)
    table = _read_with_pyarrow(raw, sep, decimal, header, text_columns, path if unchanged else None)
    if table is None:
        table = _read_with_pandas(raw.decode("utf-8"), path, sep, decimal, header, text_columns)
    del raw
    if isinstance(table, pd.DataFrame):  # a separator at the end of every line: a nameless column of nothing
        nameless = [name for name, typed in zip(table.columns, header) if not typed.strip()
                    and table[name].isna().all()]
        table = table.drop(columns=nameless)
    rows = table.num_rows if isinstance(table, pa.Table) else len(table)
    empty = _empty_rows(table)
    if empty.any():  # lines of separators only (',,,,', as spreadsheets export rows they once used): no rows
        keep = ~empty
        table = table.filter(pa.array(keep)) if isinstance(table, pa.Table) else table[keep].reset_index(drop=True)
        lines = np.asarray(lines)[keep] if len(lines) == rows else lines
    if units is not None:
        table = _with_units_in_headers(table, units.cells)
    source = CsvSource(table, None, decimal)
    if len(source) == 0:
        raise InputError(f"{path}: no {what} (only a header row{' and a units row' if units is not None else ''})")
    source.lines = RowLines(lines) if len(lines) == len(source) else None
    return source


#: a line break of a CSV text: CR LF, LF or a lone CR (as Python's csv module and _records count lines)
_LINE_BREAK = re.compile(rb"\r\n|\r|\n")


class UnitsRow(NamedTuple):
    """The units row of a CSV: its cells by header (blank and '-' cells left out) and its bytes in the file
    (start, end with its line break)."""

    cells: dict[str, str]
    span: tuple[int, int]


def _line_span(raw: bytes, number: int) -> tuple[int, int, int]:
    """(start, end of the text, end with the line break) of line ``number`` (1 for the first) of ``raw``; the
    breaks are looked for up to that line only."""
    start = 0
    for count, match in enumerate(_LINE_BREAK.finditer(raw), start=1):
        if count == number:
            return start, match.start(), match.end()
        start = match.end()
    return start, len(raw), len(raw)  # the last line, without a line break


def _units_row(path: Path, raw: bytes, sep: str, header: list[str], lines) -> UnitsRow | None:
    """The units row under the header (a CSV saved from the Excel template's sheet 'Supports': ``d`` over ``mm``),
    or None when the first row is a row of data. The rule is the Excel reader's
    (:func:`bearingheat.io.units_row.looks_like_units_row`); a cell that is no unit or contradicts its header's
    unit is refused, naming its line and column."""
    if len(lines) == 0:
        return None
    number = int(lines[0])
    start, text_end, end = _line_span(raw, number)
    text = raw[start:text_end].decode("utf-8")
    if text.count('"') % 2:  # a quoted cell that goes on in the next line: a row of data
        return None
    cells = next(csv.reader([text], delimiter=sep, skipinitialspace=True), [])
    cells += [""] * (len(header) - len(cells))
    known = input_units()
    names = [name if name in known else None for name in (parse_header(h, strict=False)[0] for h in header)]
    is_units, unknown = looks_like_units_row(cells, names)
    if unknown:
        position, why = unknown[0]
        raise InputError(f"{path}: line {number}: {why} (column {position + 1}) in the units row under the "
                         "header; write a unit such as kN, N, rpm, mm^2/s (docs/columns.md lists the columns)")
    if not is_units:
        return None
    units = {h: cell.strip() for h, cell in zip(header, cells) if h.strip() and cell.strip() not in ("", NO_UNIT)}
    for name, unit in units.items():
        if unit_contradicts_header(name, unit):
            raise InputError(f"{path}: line {number}, column {name!r}: unit {unit!r} in the units row contradicts "
                             f"the header {name!r}; keep one of them")
    return UnitsRow(units, (start, end))


def _with_units_in_headers(table: pa.Table | pd.DataFrame, units: dict[str, str]) -> pa.Table | pd.DataFrame:
    """``table`` with the units of the units row written into its headers ('d' over 'mm': 'd [mm]'), as calc and
    the other commands read them; a header that has its unit already keeps it."""
    def renamed(header: str) -> str:
        unit = units.get(header)
        return header if unit is None or parse_header(header, strict=False)[1] is not None else f"{header} [{unit}]"

    if isinstance(table, pa.Table):
        return table.rename_columns([renamed(name) for name in table.column_names])
    return table.rename(columns=renamed)


def _refuse_a_separator_the_header_lacks(path: Path, sep: str, header: str) -> None:
    """:class:`InputError` where ``--sep`` leaves the header one column that another separator would split: the
    table would otherwise be refused for its first missing column, which names no cause."""
    found = sniff_format(header)[0]
    if found != sep and found in _QUOTED.sub("", header):
        shown = header if len(header) <= 40 else header[:40] + "..."
        option = {"\t": "tab"}.get(found, found)  # as --sep takes it
        raise InputError(f"{path}: --sep {'tab' if sep == chr(9) else sep!r} leaves the header one column "
                         f"({shown!r}); its cells are separated by {SEPARATORS[found]}: give --sep {option!r} or "
                         "leave --sep out")


def _empty_rows(table: pa.Table | pd.DataFrame) -> np.ndarray:
    """The rows whose every cell is missing."""
    if isinstance(table, pd.DataFrame):
        return table.isna().all(axis=1).to_numpy()
    empty = np.ones(table.num_rows, dtype=bool)
    for column in table.columns:
        if column.null_count == 0:  # (a column without a missing cell: no row is empty)
            return np.zeros(table.num_rows, dtype=bool)
        empty &= pc.is_null(column).to_numpy(zero_copy_only=False)
    return empty
