"""Which results sheet is bearingheat's: the marks it leaves in a workbook, and the name of a new results sheet.

bearingheat replaces only a sheet it wrote itself. Each results sheet it
writes is marked by a pair of hidden, workbook-scoped defined names::

    _bearingheat_results_1   'Results'!$1:$1048576     the results sheet
    _bearingheat_input_1     Supports!$1:$1048576      the input sheet it holds the results of

They are references, so Excel and LibreOffice carry them along when a sheet
is renamed, moved or gets rows inserted or deleted; a deleted sheet turns
its reference into ``#REF!`` and the mark is dropped on the next run. A copy
of a results sheet (Excel's "Move or Copy") is not marked, so it is the
designer's. A sheet without a mark is never replaced: when it holds the name
the results sheet would get (``Results``, ``<sheet> results``) the results
go to the next free name, ``Results (2)``, and the run says so. A sheet that
:func:`~bearingheat.io.excel.writer.write_results` wrote is marked by one
name, ``_bearingheat_table_<k>``; that function replaces only a sheet one of
these marks names (:func:`written_sheets`).

>>> mark_value("Supports"), mark_value("Shaft 2 results")
('Supports!$1:$1048576', "'Shaft 2 results'!$1:$1048576")
>>> sheet_of_mark("'Q1''s loads'!$1:$1048576"), sheet_of_mark("#REF!$1:$1048576")
("Q1's loads", None)
>>> name, replace, note = choose_results_sheet(["Supports", "Results"], {}, "Supports")
>>> name, replace
('Results (2)', False)
>>> print(note)
sheet 'Results' is not a results sheet of bearingheat (it has no bearingheat mark), so it is kept; the results
of 'Supports' went to 'Results (2)'
"""
from __future__ import annotations

import re
from collections.abc import Collection, Iterable, Mapping

__all__ = ["RESULTS_MARK", "INPUT_MARK", "COMPANION_MARKS", "TABLE_MARK", "MAX_SHEET_NAME", "mark_value",
           "sheet_of_mark", "read_marks", "read_companions", "written_sheets", "table_mark_slots",
           "choose_results_sheet", "choose_companion_sheet", "candidate_names", "sheet_ref", "sheet_name_problem"]

RESULTS_MARK = "_bearingheat_results_"
INPUT_MARK = "_bearingheat_input_"
#: Excel's longest sheet name
MAX_SHEET_NAME = 31
_WHOLE_SHEET = "$1:$1048576"
_MARK_NAME = re.compile(rf"^({RESULTS_MARK}|{INPUT_MARK})(\d+)$", re.IGNORECASE)
#: the further sheets a results sheet may have, by role: the hidden copy of the inputs it was computed from
#: (``calc --formulas``, :mod:`.freshness`) and the summary of a duty cycle; marked like the results sheet,
#: ``_bearingheat_snapshot_<k>`` and ``_bearingheat_duty_<k>`` of pair k
COMPANION_MARKS = {"snapshot": "_bearingheat_snapshot_", "duty": "_bearingheat_duty_"}
_COMPANION_NAME = re.compile(r"^_bearingheat_(snapshot|duty)_(\d+)$", re.IGNORECASE)
#: the mark of a sheet that :func:`bearingheat.io.excel.writer.write_results` wrote, ``_bearingheat_table_<k>``
TABLE_MARK = "_bearingheat_table_"
_TABLE_NAME = re.compile(rf"^{TABLE_MARK}(\d+)$", re.IGNORECASE)


#: a name Excel would read as a cell reference: A1 form (A1, XFD1) or R1C1 form (R, C, RC, R1C1, R2C, C3)
_LOOKS_LIKE_A_CELL = re.compile(r"[A-Za-z]{1,3}[0-9]+|[Rr][0-9]*[Cc]?[0-9]*|[Cc][0-9]*")


def sheet_ref(sheet: str) -> str:
    """A sheet name as every formula, defined name and message of bearingheat writes it before '!': as it is
    where Excel reads it so (letters, digits, underscore and dot, not starting with a digit or dot), else in
    apostrophes with an apostrophe doubled: a name Excel would read as a cell reference in A1 or R1C1 form
    ('C', 'R1C1', 'XFD1'), a logical value, and any other name ('Shaft 1', "Q1's loads", '2024').

    >>> [sheet_ref(s) for s in ("Supports", "Cases", "Shaft_1.2", "C", "R", "RC", "R1C1", "A1", "XFD1", "TRUE")]
    ['Supports', 'Cases', 'Shaft_1.2', "'C'", "'R'", "'RC'", "'R1C1'", "'A1'", "'XFD1'", "'TRUE'"]
    >>> [sheet_ref(s) for s in ("Shaft 1", "Q1's loads", "2024", "G-17", "Опоры")]
    ["'Shaft 1'", "'Q1''s loads'", "'2024'", "'G-17'", "'Опоры'"]
    """
    plain = re.fullmatch(r"[A-Za-z_][A-Za-z0-9_.]*", sheet) is not None
    if plain and not _LOOKS_LIKE_A_CELL.fullmatch(sheet) and sheet.upper() not in ("TRUE", "FALSE"):
        return sheet
    return "'" + sheet.replace("'", "''") + "'"


def mark_value(sheet: str) -> str:
    """The value of a mark: every row of ``sheet`` (a reference that survives row and column edits)."""
    return f"{sheet_ref(sheet)}!{_WHOLE_SHEET}"


def sheet_of_mark(value: str | None) -> str | None:
    """The sheet a mark's value refers to; None for a broken (``#REF!``) or foreign value."""
    if not value:
        return None
    text = value.strip().lstrip("=")
    match = re.fullmatch(r"'((?:[^']|'')+)'!(.+)|([^'!]+)!(.+)", text)
    if match is None:
        return None
    sheet = match.group(1).replace("''", "'") if match.group(1) is not None else match.group(3)
    if sheet.startswith("#REF") or "#REF" in (match.group(2) or match.group(4)):
        return None
    return sheet


def read_marks(names: Iterable[tuple[str, str | None]]) -> dict[int, tuple[str | None, str | None]]:
    """{k: (results sheet, input sheet)} from (defined name, value) pairs of workbook scope."""
    marks: dict[int, list] = {}
    for name, value in names:
        match = _MARK_NAME.match(name or "")
        if match is None:
            continue
        slot = marks.setdefault(int(match.group(2)), [None, None])
        slot[0 if match.group(1).lower() == RESULTS_MARK else 1] = sheet_of_mark(value)
    return {k: (v[0], v[1]) for k, v in sorted(marks.items())}


def read_companions(names: Iterable[tuple[str, str | None]]) -> dict[int, dict[str, str | None]]:
    """{k: {role: sheet}} of the companion marks (:data:`COMPANION_MARKS`) among (defined name, value) pairs.

    >>> read_companions([("_bearingheat_snapshot_1", "'Calc inputs'!$1:$1048576"), ("other", "A1")])
    {1: {'snapshot': 'Calc inputs'}}
    """
    out: dict[int, dict[str, str | None]] = {}
    for name, value in names:
        match = _COMPANION_NAME.match(name or "")
        if match is not None:
            out.setdefault(int(match.group(2)), {})[match.group(1).lower()] = sheet_of_mark(value)
    return out


def written_sheets(names: Iterable[tuple[str, str | None]]) -> dict[str, str]:
    """The sheets bearingheat wrote, by their names without case -> name: the results sheets, their companions
    and the tables of :data:`TABLE_MARK`, from (defined name, value) pairs of workbook scope (the input sheets
    their marks name are the designer's).

    >>> written_sheets([("_bearingheat_results_1", "Results!$1:$1048576"), ("_bearingheat_input_1",
    ...                 "Supports!$1:$1048576"), ("_bearingheat_table_2", "'Loads'!$1:$1048576")])
    {'results': 'Results', 'loads': 'Loads'}
    """
    pairs = list(names)
    sheets = [results for results, _ in read_marks(pairs).values()]
    sheets += [sheet for roles in read_companions(pairs).values() for sheet in roles.values()]
    sheets += [sheet_of_mark(value) for name, value in pairs if _TABLE_NAME.match(name or "")]
    return {sheet.casefold(): sheet for sheet in sheets if sheet is not None}


def table_mark_slots(names: Iterable[str]) -> set[int]:
    """The numbers k of the ``_bearingheat_table_<k>`` marks among defined names."""
    return {int(match.group(1)) for name in names if (match := _TABLE_NAME.match(name or ""))}


#: the characters Excel does not allow in a sheet name
_NOT_IN_SHEET_NAMES = "\\/?*:[]"


def sheet_name_problem(name: str) -> str | None:
    """Why Excel would not take ``name`` as a sheet name; None when it would.

    >>> print(sheet_name_problem("Loads"))
    None
    >>> print(sheet_name_problem("Loads/2"))
    has the character '/', which Excel does not allow in a sheet name (none of \\ / ? * : [ ])
    >>> sheet_name_problem("Gearbox G-17 intermediate shaft loads")
    'has 37 characters; Excel allows at most 31'
    """
    if not name.strip():
        return "is blank; a sheet needs a name"
    if len(name) > MAX_SHEET_NAME:
        return f"has {len(name)} characters; Excel allows at most {MAX_SHEET_NAME}"
    bad = next((c for c in name if c in _NOT_IN_SHEET_NAMES), None)
    if bad is not None:
        return (f"has the character {bad!r}, which Excel does not allow in a sheet name (none of "
                f"{' '.join(_NOT_IN_SHEET_NAMES)})")
    if name.startswith("'") or name.endswith("'"):
        return "begins or ends with an apostrophe, which Excel does not allow"
    if name.casefold() == "history":
        return "is reserved by Excel (for a shared workbook's change history)"
    return None


def choose_companion_sheet(sheets: list[str], current: str | None, base: str, taken: Collection[str] = ()
                           ) -> tuple[str, bool]:
    """(name, replace it?) of a companion sheet: the sheet its mark names (``current``) where it still exists,
    else the first free name of ``base`` (not in ``sheets`` nor ``taken``, compared without case).

    >>> choose_companion_sheet(["Supports", "Duty cycle"], None, "Duty cycle", ["Results"])
    ('Duty cycle (2)', False)
    """
    present = {s.casefold(): s for s in sheets}
    if current is not None and current.casefold() in present:
        return present[current.casefold()], True
    used = set(present) | {t.casefold() for t in taken}
    tail = next((t for t in (" calc inputs", " duty cycle", " results") if base.endswith(t)), "")
    return next(n for n in candidate_names(base, tail) if n.casefold() not in used), False


def candidate_names(base: str, tail: str | None = None) -> Iterable[str]:
    """``base``, then ``base (2)``, ``base (3)`` ... each at most 31 characters; a ``<sheet> results`` base keeps
    its word 'results' (or another ``tail``) and gives up characters of the sheet name instead.

    >>> [name for name, _ in zip(candidate_names("Results"), range(3))]
    ['Results', 'Results (2)', 'Results (3)']
    >>> [name for name, _ in zip(candidate_names("Gearbox G-17 intermedia results"), range(2))]
    ['Gearbox G-17 intermedia results', 'Gearbox G-17 interm results (2)']
    """
    if tail is None:
        tail = " results" if base.endswith(" results") else ""
    stem = base[:-len(tail)] if tail and base.endswith(tail) else base
    tail = tail if base.endswith(tail) else ""
    yield stem[:MAX_SHEET_NAME - len(tail)] + tail
    k = 2
    while True:
        suffix = f"{tail} ({k})"
        yield stem[:MAX_SHEET_NAME - len(suffix)] + suffix
        k += 1


def _owner_text(sheet: str, input_sheet: str, owners: Mapping[str, str]) -> str:
    if sheet.casefold() == input_sheet.casefold():
        return f"sheet {sheet!r} is the input sheet"
    other = owners.get(sheet.casefold())
    if other is not None:
        return f"sheet {sheet!r} holds the results of sheet {other!r}"
    return f"sheet {sheet!r} is not a results sheet of bearingheat (it has no bearingheat mark), so it is kept"


def choose_results_sheet(sheets: list[str], marks: Mapping[int, tuple[str | None, str | None]],
                         input_sheet: str, base: str | None = None,
                         placeholders: Collection[str] = ()) -> tuple[str, bool, str | None]:
    """(results sheet name, replace it?, note) for the results of ``input_sheet``.

    ``sheets`` are the workbook's sheet names, ``marks`` :func:`read_marks`.
    A marked results sheet of ``input_sheet`` is replaced whatever its name
    now is; so is an unmarked sheet of the name ``base`` that is in
    ``placeholders`` (the empty 'Results' sheet of bearingheat's template,
    which holds nothing of the designer's). Otherwise the first free name of
    :func:`candidate_names` (Excel compares sheet names without case) is
    taken, with a note when it is not ``base`` (default: ``Results`` for
    'Supports', else ``<first 23 characters> results``).
    """
    if base is None:
        base = "Results" if input_sheet == "Supports" else f"{input_sheet[:23]} results"
    present = {s.casefold(): s for s in sheets}
    for results, source in marks.values():
        if (results is not None and source == input_sheet and results.casefold() in present
                and results.casefold() != input_sheet.casefold()):
            return present[results.casefold()], True, None
    owned = {r.casefold() for r, _ in marks.values() if r is not None}
    holder = present.get(base.casefold())
    if (holder is not None and holder in placeholders and holder.casefold() not in owned
            and holder.casefold() != input_sheet.casefold()):
        return holder, True, None
    owners = {r.casefold(): s for r, s in marks.values() if r is not None and s is not None}
    for name in candidate_names(base):
        if name.casefold() not in present:
            if name == base:
                return name, False, None
            first = present.get(base.casefold(), base)
            return name, False, f"{_owner_text(first, input_sheet, owners)}; the results of {input_sheet!r} went " \
                                f"to {name!r}"
    raise AssertionError("unreachable")  # pragma: no cover
