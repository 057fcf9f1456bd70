"""Never a stale number: the inputs each results row was computed from, and a live check against them.

With ``calc --formulas`` the workbook keeps a hidden copy of the input
cells calc read (the *inputs snapshot* sheet, e.g. ``Calc inputs``, laid out
cell for cell like the input sheet). The status cell of every results row
is a formula that compares the row's input cells with that copy:

- all inputs as computed: the status calc gave (ok, warning, error);
- an input changed: ``recalculate with bearingheat`` (:data:`NOTE`), and a
  conditional format strikes through the results that are values, not
  formulas (n_thr, n_per, T_op, nu_op, Q_S, Q_L and every other column of
  an extension): they came from a root or a table and do not follow;
- an input changed that the row's live formulas do not follow (the
  designation, type, series, arrangement, model, contact angle; any input
  of a row whose formulas use a value of the operating point, such as a
  viscosity from the oil's curve or an f2 read off the chart):
  ``recalculate with bearingheat (every result)`` (:data:`NOTE_EVERY`), and
  every result of the row is struck through.

- a header or a unit changed (a cell of the header row or the units row,
  from the first to the last column calc read; the copy keeps them too, and
  one SUMPRODUCT compares them, so the formula stays short on a wide
  sheet): :data:`NOTE_EVERY` on every
  row, as calc would read the column anew (another unit, another quantity)
  and the live formulas have the unit's factor built in (``*1000`` of kN).

A support typed on the input sheet after the run has no results row, so no
status can speak for it: a cell under the results counts the filled rows of
the input sheet against calc's count and says how many supports have no
results (:func:`unread_rows_check`).

Running calc again writes a new copy, so the marks go. The values of the
label column ``id`` are not compared (its header is). Text is compared without case, as Excel's ``<>``
does (calc reads the lubrication as typed, so a change of case alone
would not be caught).

>>> check = FreshnessCheck("Supports", [3], {"n": "E", "designation": "B"}, ["ok"],
...                        [frozenset({"designation"})], [], "$A$1:$E$2")
>>> print(check.status_formulas("Calc inputs")[0].replace("),", "),\\n"))
=IF(OR(SUMPRODUCT(--(Supports!$A$1:$E$2<>'Calc inputs'!$A$1:$E$2))>0,Supports!B3<>'Calc inputs'!B3),
"recalculate with bearingheat (every result)",IF(OR(Supports!E3<>'Calc inputs'!E3),
"recalculate with bearingheat","ok"))
"""
from __future__ import annotations

from dataclasses import dataclass

from openpyxl.utils import get_column_letter

from bearingheat.errors import ExcelError
from bearingheat.io.excel import style as st
from bearingheat.io.excel.ownership import sheet_ref

__all__ = ["NOTE", "NOTE_EVERY", "FreshnessCheck", "ConditionalRule", "snapshot_base", "freshness_check",
           "conditional_rules", "unread_rows_check"]

NOTE = "recalculate with bearingheat"
#: the most characters a formula may have in Excel (Excel specifications and limits)
EXCEL_FORMULA_LENGTH = 8192
NOTE_EVERY = "recalculate with bearingheat (every result)"
#: columns of a results sheet that are never struck through: the row, the label, the status and its message
_NOT_RESULTS = ("row", "id", "status", "message")
#: text that holds as long as the formulas do (the load of M1 follows the bearing type and arrangement)
_WITH_THE_FORMULAS = ("M1 load",)


def snapshot_base(input_sheet: str) -> str:
    """The name of the inputs snapshot of ``input_sheet``: 'Calc inputs', or '<sheet> calc inputs'."""
    return "Calc inputs" if input_sheet == "Supports" else f"{input_sheet[:19]} calc inputs"


@dataclass(frozen=True)
class ConditionalRule:
    """A conditional format: the cells (``sqref``), the formula (relative to the first cell) and the
    differential format's name (:data:`bearingheat.io.excel.style.DIFFERENTIAL`)."""

    sqref: str
    formula: str
    dxf: str


@dataclass
class FreshnessCheck:
    """The live check of one results sheet.

    ``rows`` are the input sheet's rows of the results rows, ``letters`` the
    compared input columns (contract name -> column letter), ``statuses``
    calc's status of each row, ``every`` per row the inputs whose change
    makes every result stale (None: any input), ``snapshot`` the cells of
    the copy as (row, column index, value), ``titles`` the block of header and units
    cells ('$A$1:$AZ$2') whose change makes every result of every row stale.
    """

    input_sheet: str
    rows: list[int]
    letters: dict[str, str]
    statuses: list[str]
    every: list[frozenset[str] | None]
    snapshot: list[tuple[int, int, object]]
    titles: str | None = None

    def status_formulas(self, snapshot_sheet: str) -> list[str]:
        """The formula of every status cell, comparing the input sheet with ``snapshot_sheet``."""
        here, copy = sheet_ref(self.input_sheet), sheet_ref(snapshot_sheet)
        names = sorted(self.letters, key=lambda n: (len(self.letters[n]), self.letters[n]))
        out = []
        for row, status, every in zip(self.rows, self.statuses, self.every):
            def differ(cells):
                return ",".join(f"{here}!{cell}<>{copy}!{cell}" for cell in cells)
            strict = names if every is None else [n for n in names if n in every]
            rest = [n for n in names if n not in strict]
            text = '"' + str(status).replace('"', '""') + '"'
            if rest:
                text = f'IF(OR({differ(self.letters[n] + str(row) for n in rest)}),"{NOTE}",{text})'
            # a header or unit typed anew: calc would read the column otherwise (kN -> N is a factor of 1000
            # that the live formulas have built in), so every result of every row is stale
            stale_all = [differ(self.letters[n] + str(row) for n in strict)] if strict else []
            if self.titles is not None:
                stale_all.insert(0, f"SUMPRODUCT(--({here}!{self.titles}<>{copy}!{self.titles}))>0")
            if stale_all:
                text = f'IF(OR({",".join(stale_all)}),"{NOTE_EVERY}",{text})'
            out.append("=" + text)
        return out


def freshness_check(ws, table, info, statuses, every) -> FreshnessCheck:
    """The check of the rows of ``info`` (:class:`bearingheat.io.excel.reader.SheetInfo`) read from the
    openpyxl worksheet ``ws``: the copy holds the cells as stored (formula cells: the value calc read), and
    the header and units rows."""
    letters = {name: info.letters[header] for name, header in info.headers.items() if name != "id"}
    snapshot: list[tuple[int, int, object]] = []
    cells = ws._cells
    # the header and units rows from the first to the last column read, every cell of them (a header typed
    # over a column calc passed by changes the reading as well)
    columns = [_column_index(info.letters[header]) for header in info.headers.values()]
    last_title = info.last_title_row
    titles = None
    if columns:
        first, last = min(columns), max(columns)
        titles = f"${get_column_letter(first)}${info.header_row}:${get_column_letter(last)}${last_title}"
        for row in range(info.header_row, last_title + 1):
            for col in range(first, last + 1):
                value = cells[(row, col)].value if (row, col) in cells else None
                if value is not None:
                    snapshot.append((row, col, value if isinstance(value, (str, int, float, bool)) else str(value)))
    for name, header in info.headers.items():
        col = _column_index(info.letters[header])
        if name == "id":
            continue
        for position, row in enumerate(info.rows):
            cell = cells.get((row, col))
            value = None if cell is None else cell.value
            if (cell is not None and cell.data_type == "f") or not isinstance(value, (str, int, float, bool,
                                                                                         type(None))):
                value = table[header].iloc[position]  # a formula cell: the value the spreadsheet saved
            if value is not None and not (isinstance(value, float) and value != value):
                snapshot.append((row, col, value))
    return FreshnessCheck(info.sheet, list(info.rows), letters, [str(s) for s in statuses], list(every), snapshot,
                          titles)


def unread_rows_check(info, results: int) -> tuple[str, str, ConditionalRule] | None:
    r'''The check that the input sheet has no supports without results: (address, formula, conditional format) of
    a cell in column A under the ``results`` rows of the results sheet, after one blank row (so that Excel's sort
    and filter do not take it for a row of the table); None for a sheet without contract columns.

    The formula counts the rows of the input sheet with something in a column calc read, from the units row
    (the header row without one: a support inserted above the first stays inside the ranges) to the last row,
    as ROWS less the rows that COUNTIFS finds blank in every such column, and compares the count with the same
    count when calc ran (:attr:`bearingheat.io.excel.reader.SheetInfo.filled_rows`: a totals row, a row of
    spaces counted alike). More rows: "sheet 'Supports' has 2 supports without results: recalculate with
    bearingheat" (bold orange); else empty text. The words of 1 or more come from TEXT's conditional number
    format, so the long count is written twice, not three times (a formula has at most 8192 characters).

    >>> from types import SimpleNamespace
    >>> info = SimpleNamespace(sheet="C", last_title_row=2, headers={"Fr": "Fr", "designation": "B"},
    ...                        letters={"Fr": "F", "B": "B"}, filled_rows=7)
    >>> address, formula, rule = unread_rows_check(info, 6)
    >>> address, rule.sqref, rule.formula
    ('A10', 'A10', 'LEN($A$10)>0')
    >>> print(formula.replace(">7,", ">7,\n").replace("-7,", "-7,\n"))
    =IF(ROWS('C'!B2:B1048576)-COUNTIFS('C'!B2:B1048576,"",'C'!F2:F1048576,"")>7,
    "sheet 'C' has "&TEXT(ROWS('C'!B2:B1048576)-COUNTIFS('C'!B2:B1048576,"",'C'!F2:F1048576,"")-7,
    "[=1]""1 support"";0"" supports""")&" without results: recalculate with bearingheat","")
    '''
    letters = sorted({info.letters[header] for header in info.headers.values()}, key=lambda c: (len(c), c))
    if not letters:
        return None
    here = sheet_ref(info.sheet)
    first = info.last_title_row
    ranges = [f"{here}!{letter}{first}:{letter}1048576" for letter in letters]
    count = f'ROWS({ranges[0]})-COUNTIFS({",".join(r + "," + chr(34) * 2 for r in ranges)})'
    sheet = repr(info.sheet).replace('"', '""')
    supports = '"[=1]""1 support"";0"" supports"""'
    formula = (f'=IF({count}>{info.filled_rows},"sheet {sheet} has "&TEXT({count}-{info.filled_rows},{supports})'
               f'&" without results: {NOTE}","")')
    if len(formula) > EXCEL_FORMULA_LENGTH:  # (only a sheet name of many apostrophes comes near)
        raise ExcelError(f"--formulas: the check of sheet {info.sheet!r} for supports without results would be a "
                         f"formula of {len(formula)} characters, more than Excel's {EXCEL_FORMULA_LENGTH}; give the "
                         "sheet a shorter name")
    address = f"A{results + 4}"
    return address, formula, ConditionalRule(address, f"LEN($A${results + 4})>0", st.RECALCULATE)


def _column_index(letter: str) -> int:
    index = 0
    for char in letter:
        index = index * 26 + ord(char.upper()) - 64
    return index


def conditional_rules(columns: list[str], live_columns: list[str], n_rows: int) -> list[ConditionalRule]:
    """The conditional formats of a results sheet with a live check (``columns`` its headers in order, data
    in rows 3 to n_rows + 2): values (and the copies of inputs such as the designation) struck on
    :data:`NOTE`, formulas on :data:`NOTE_EVERY`, the status coloured."""
    if "status" not in columns or not n_rows:
        return []
    status = get_column_letter(columns.index("status") + 1)
    last = n_rows + 2
    note = f'LEFT(${status}3,{len(NOTE)})="{NOTE}"'

    def sqref(headers):
        letters = [columns.index(h) + 1 for h in headers]
        spans, start = [], None
        for k, col in enumerate(letters):
            start = col if start is None else start
            if k + 1 == len(letters) or letters[k + 1] != col + 1:
                spans.append(f"{get_column_letter(start)}3:{get_column_letter(col)}{last}")
                start = None
        return " ".join(spans)

    results = [h for h in columns if h not in _NOT_RESULTS]  # the copies of inputs (designation ...) too
    live = [h for h in results if h in live_columns or h in _WITH_THE_FORMULAS]
    values = [h for h in results if h not in live]
    rules = []
    if values:
        rules.append(ConditionalRule(sqref(values), note, st.STALE))
    if live:
        rules.append(ConditionalRule(sqref(live), f'${status}3="{NOTE_EVERY}"', st.STALE))
    rules.append(ConditionalRule(f"{status}3:{status}{last}", note, st.RECALCULATE))
    return rules
