"""The DataFrame API: the ``bearingheat calc`` column contract on pandas.

Input columns are headed ``name [unit]`` where the unit is any pint unit of
the right dimension (``Fr [kN]``, ``n [rpm]``, ``n [Hz]``, ``nu [cSt]``).
The columns, their catalogue units and meanings are the column contract,
:mod:`bearingheat.calc.contract`; each row's friction model is the
``model`` column or the ``model`` argument (:mod:`bearingheat.calc.models`).

Result columns: the model's results (``f0``, ``f1``, ``P0 [N]``, ``P1 [N]``,
``M0 [N*mm]``, ``M1 [N*mm]``, ``M2 [N*mm]``, ``MR [N*mm]``, ``NR [W]`` for
the catalogue model), ``status`` (ok | warning | error) and ``message``;
``Fa/A`` and ``nu*n*dM [mm^3/(s*min)]`` when a row carries M2. Extensions
(the heat balance, contact checks) add their own columns when their inputs
are present.

A bad row gets ``status = error`` and a message naming the column and the
value; the other rows are still computed. Input that cannot be used at all
(a required column missing, a unit of the wrong dimension) raises
:class:`~bearingheat.errors.InputError`.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np
import pandas as pd
import pyarrow as pa

from bearingheat.calc import contact, thermal
from bearingheat.calc.thermal import (DEFAULT_SPEED_FACTOR_METHOD, DEFAULT_VISCOSITY_AT, SPEED_FACTOR_METHODS,
                                     VISCOSITY_AT)
from bearingheat.calc.contract import PLAIN_TYPES, TEXT_DTYPE, input_units, output_header, output_units
from bearingheat.calc.messages import ERROR, WARNING, status_codes, status_column, with_texts
from bearingheat.calc.supports import blanks_filled, per_distinct, with_bearing_groups
from bearingheat.calc.distributed import calc_dask, is_dask_frame
from bearingheat.calc.conversion import refuse_result_columns, results_spelled_otherwise, to_catalogue_units
from bearingheat.calc.fill import fill_from_catalogue, implausible_relations, minimum_load_relations
from bearingheat.calc.uncertainty import fill_from_coefficients, has_uncertainty, uncertainty_bands
from bearingheat.calc.models import (DEFAULT_MODEL, M2_REPORT_UNITS, MODEL_REPORT_UNITS, PLAIN_REPORT_UNITS,
                                     RESULT_UNITS, SKF, compute_supports, failed_rows, row_model_names)
from bearingheat.catalogue.f2chart import F2Chart
from bearingheat.catalogue.vm_chart import VMChart
from bearingheat.calc.skf import fill_vm_from_chart
from bearingheat.errors import InputError

__all__ = ["calc", "compute_table", "ComputedTable", "require_columns", "Extension", "EXTENSIONS"]


@dataclass(frozen=True)
class Extension:
    """A calc extension: it reads and writes the contract columns of its ``owner``.

    ``prepare(frame) -> (frame, problems)`` runs before the friction model,
    ``settle(frame, results, f2_chart=, labels=, model=) -> (frame, results,
    problems)`` right after it (an input that needs the friction results,
    such as a viscosity at the operating temperature; None: nothing to
    settle), ``extend(frame, results, f2_chart=, labels=, model=) -> (columns,
    problems)`` after the messages (the options of the friction pass, for a
    result that evaluates the model again); problems are (row position,
    'error' | 'warning', message).
    """

    owner: str
    prepare: Callable
    extend: Callable
    settle: Callable | None = None


#: the extensions in the order their columns are written; keys are the contract owners
EXTENSIONS: dict[str, Extension] = {e.owner: e for e in (
    Extension("contact", contact.prepare, contact.extend),
    Extension("thermal", thermal.prepare, thermal.extend, thermal.settle),
)}


def require_columns(frame: pd.DataFrame) -> None:
    """Raise :class:`InputError` naming the first required column the frame (contract names) lacks."""
    have = set(frame.columns)
    rolling = np.ones(len(frame), dtype=bool)
    if "type" in have:
        types = per_distinct(frame["type"], lambda v: str(v).lower() if isinstance(v, str) else "")
        rolling = ~pd.Series(types, dtype=object).isin(PLAIN_TYPES).to_numpy()
    if "n" not in have:
        raise InputError("missing column: 'n [1/min]' (any n unit of the right dimension)")
    if not rolling.any():
        return
    if "designation" not in have and not {"type", "series"} <= have:
        raise InputError("missing column: 'designation' (or 'type' and 'series')")
    for name in ("D", "nu"):
        if name not in have:
            unit = input_units()[name]
            raise InputError(f"missing column: '{name} [{unit}]' (any {name} unit of the right dimension)")
    if "lubrication" not in have and "f0" not in have:
        raise InputError("missing column: 'lubrication' (grease, oil_mist, oil_bath or circulating_oil)")


def calc(table: pd.DataFrame, *, model: str = DEFAULT_MODEL, f2_chart: F2Chart | str | None = None,
         vm_chart: VMChart | str | None = None,
         units: dict[str, str] | None = None, cell: Callable[[str, int], str] | None = None,
         effects=None, n_per_method: str = DEFAULT_SPEED_FACTOR_METHOD,
         viscosity_at: str = DEFAULT_VISCOSITY_AT, coefficients: pd.DataFrame | str | None = None,
         uncertainty: str = "linearised", decimal: str = ".") -> pd.DataFrame:
    """Run the friction model (and its extensions) on a table of supports.

    Returns the input columns followed by the result columns. ``model`` is
    the friction model of rows whose ``model`` cell is blank (a name of
    :data:`bearingheat.calc.models.MODELS`; an unknown name raises
    :class:`~bearingheat.errors.ModelError`). ``effects`` is an optional
    fitted extension of the model (``bearingheat diagnose``) applied to MR
    and NR.

    The friction model is the one of the Schaeffler rolling bearing
    catalogue (Russian edition), chapter «Трение и нагрев» (Friction and
    increases in temperature), with f0, f1 after ISO 15312; the ``thermal``
    extension adds the heat balance of the Schaeffler catalogue HR 1
    "Rolling bearings" (edition June 2006, after ISO 15312 and the draft of
    DIN 732) where its columns are present, the ``contact`` extension the
    minimum axial load of ball bearings (В.А. Зайцев, В.А. Воронкин, ФГУП
    «НПП ВНИИЭМ», 2009). A bad row gets ``status`` 'error' and a message
    naming the column and the value; the other rows are still computed.
    Numbers outside a column's valid range are row errors, outside its
    plausible range row warnings (the ranges of
    :mod:`bearingheat.calc.contract`, e.g. n up to 1e7 1/min, T_amb -60 to
    200 °C, alpha 0 to 90°), as are a load above C0 and a speed above the
    limiting speed n_G.

    Parameters
    ----------
    table : pandas.DataFrame
        One row per support, columns headed ``name [unit]`` with any pint
        unit of the right dimension (``Fr [kN]``, ``n [rpm]``, ``nu [cSt]``);
        the columns of the column contract (:mod:`bearingheat.calc.contract`).
        Required: ``n``, and for rolling bearings ``designation`` (or
        ``type`` and ``series``), ``D``, ``nu`` and ``lubrication`` (or
        ``f0``). Unknown columns are passed through untouched.
    model : str, optional
        Friction model of rows whose ``model`` cell is blank: 'schaeffler'
        (default) or 'skf' (the SKF four-component model of the SKF General
        Catalogue 6000, chapter Friction, and SKF Rolling bearings 10000/3,
        2017, which adds its own result columns).
    f2_chart : F2Chart or str, optional
        A digitised f2 chart (:class:`~bearingheat.catalogue.f2chart.F2Chart`),
        or the path of its CSV, for M2 of axially loaded cylindrical roller
        bearings.
    vm_chart : VMChart or str, optional
        A digitised chart of the SKF drag loss factor VM against H/dm
        (:class:`~bearingheat.catalogue.vm_chart.VMChart`), or the path of
        its CSV: oil-bath rows of the SKF model with a blank VM read it off
        the chart of their edition and kind (never extrapolated); the column
        ``VM_chart`` shows the value read.
    units : dict of str to str, optional
        Header -> unit typed in a separate units row (Excel); a unit in the
        header itself wins.
    cell : callable, optional
        ``cell(name, row position) -> str`` naming a cell in messages (e.g.
        the workbook cell of a value).
    effects : bearingheat.analysis.diagnose.FittedEffect, optional
        A fitted effect of ``bearingheat diagnose`` applied to MR and NR; a row whose model is not the
        one it was fitted on is an error, a row outside its fitted domain a warning.
    n_per_method : str, optional
        How n_per finds its speed factor where the ``n_per_method`` cell is
        blank: 'exact' (default) or 'approximation'.
    coefficients : pandas.DataFrame or str, optional
        The ``coefficients.csv`` of ``bearingheat audit`` (or its path):
        the relative half-widths of the fitted f0 and f1 intervals become
        the ``f0_rel_unc`` and ``f1_rel_unc`` of rows with that designation
        where the table leaves them blank.
    uncertainty : str, optional
        How rows with ``f0_rel_unc`` or ``f1_rel_unc`` get their 95 % bands
        ``MR_low``, ``MR_high``, ... (:mod:`bearingheat.calc.uncertainty`):
        'linearised' (default) or 'sampled'.
    viscosity_at : str, optional
        Where a viscosity from oil data (``nu40``/``nu100`` or ``iso_vg``)
        is taken for the friction results of rows whose ``viscosity_at``
        cell is blank: 'auto' (default: at the solved operating temperature
        T_op where ``T_amb`` and ``n`` are given, so that MR, NR, T_op and
        nu_op are one operating state; else at ``T_bearing``), 'operating'
        (T_op) or 'bearing' (``T_bearing``, the temperature n_per is found
        for). The columns ``nu_used`` and ``nu_at`` say which was used.
    decimal : str, optional
        The decimal mark of numbers typed as text in number columns: '.'
        (default) or ',' (a European CSV: ``'3,2'`` is 3.2, and ``'1.480'``
        is no number). Cells that are numbers are read as they are.

    Returns
    -------
    pandas.DataFrame
        The input columns (same index) followed by the result columns:
        ``f0``, ``f1``, ``P0 [N]``, ``P1 [N]``, ``M0 [N*mm]``,
        ``M1 [N*mm]``, ``M2 [N*mm]``, ``MR [N*mm]``, ``NR [W]`` (catalogue
        model), ``Fa/A`` and ``nu*n*dM [mm^3/(s*min)]`` when a row carries
        M2, the extension columns whose inputs are present (``n_thr``,
        ``n_per``, ``T_op`` ..., ``Fa_min``), ``status`` ('ok', 'warning'
        or 'error') and ``message``. Results of rows in error are NaN.

    Raises
    ------
    bearingheat.errors.InputError
        For a table that cannot be used at all: a required column missing,
        a column given twice, a header unit of the wrong dimension or an
        unknown unit, an unknown ``n_per_method``.
    bearingheat.errors.ModelError
        For an unknown model name.
    bearingheat.errors.F2ChartError
        For an f2 chart file that cannot be read or used.

    Examples
    --------
    >>> import pandas as pd
    >>> rows = pd.DataFrame({"designation": ["6205", "NU206-E"], "d [mm]": [25, 30], "D [mm]": [52, 62],
    ...                      "C0 [kN]": [7.8, 36], "lubrication": ["oil_bath", "grease"],
    ...                      "n [rpm]": [3000, 1500], "Fr [kN]": [2, 5], "nu [mm^2/s]": [12, 20]})
    >>> out = calc(rows)
    >>> out[["MR [N*mm]", "NR [W]", "status"]].round(3)
       MR [N*mm]  NR [W] status
    0     47.535  14.932     ok
    1     81.217  12.757     ok
    """
    if is_dask_frame(table):  # lazily, partition by partition (bearingheat.calc.distributed)
        return calc_dask(table, calc, model=model, f2_chart=f2_chart, vm_chart=vm_chart, units=units, effects=effects,
                         n_per_method=n_per_method, viscosity_at=viscosity_at, coefficients=coefficients,
                         uncertainty=uncertainty, decimal=decimal)
    computed = compute_table(table, model=model, f2_chart=f2_chart, vm_chart=vm_chart, units=units, cell=cell,
                             effects=effects, n_per_method=n_per_method, viscosity_at=viscosity_at, decimal=decimal)
    frame, results = computed.frame, computed.results
    out = _assemble(table, results, computed.extension_columns.values())
    if coefficients is not None:
        table = fill_from_coefficients(table, pd.read_csv(coefficients) if isinstance(coefficients, str)
                                       else coefficients)
        again = to_catalogue_units(table, units=units, cell=cell, decimal=decimal)
        frame = fill_from_catalogue(again.frame, again.labels)[0]  # the uncertainty columns, the same fill
    if has_uncertainty(table):
        def recalc(perturbed: pd.DataFrame) -> pd.DataFrame:
            return calc(perturbed, model=model, f2_chart=f2_chart, vm_chart=vm_chart, units=units, effects=effects,
                        n_per_method=n_per_method, viscosity_at=viscosity_at, decimal=decimal)
        bands = uncertainty_bands(table, out, frame.reset_index(drop=True).set_axis(out.index), recalc,
                                  method=uncertainty)
        out = pd.concat([out.drop(columns=["status", "message"]), bands, out[["status", "message"]]], axis=1)
    return out


@dataclass(frozen=True)
class ComputedTable:
    """What :func:`calc` computes of a table before it writes its result frame, in catalogue units, with the
    table's index: ``frame``, the inputs after the fills from the bearing table and the oil data and the
    extensions' settling (hidden ``_`` columns included); ``results``, the friction results with ``status`` and
    ``message``, every row's messages in place; ``extension_columns``, owner -> (columns, units) of each
    extension (``thermal``: n_thr, n_per, T_op ...) and of the VM chart (``skf``)."""

    frame: pd.DataFrame
    results: pd.DataFrame
    extension_columns: dict[str, tuple[pd.DataFrame, dict[str, str]]]


def compute_table(table: pd.DataFrame, *, model: str = DEFAULT_MODEL, f2_chart: F2Chart | str | None = None,
                  vm_chart: VMChart | str | None = None, units: dict[str, str] | None = None,
                  cell: Callable[[str, int], str] | None = None, effects=None,
                  n_per_method: str = DEFAULT_SPEED_FACTOR_METHOD, viscosity_at: str = DEFAULT_VISCOSITY_AT,
                  decimal: str = ".") -> ComputedTable:
    """The rows of ``table`` computed as :func:`calc` computes them (its arguments), before its result frame:
    what ``bearingheat plot`` draws a row's heat balance from. Raises as :func:`calc` does."""
    if isinstance(f2_chart, str):
        f2_chart = F2Chart.from_csv(f2_chart)
    if isinstance(vm_chart, str):
        vm_chart = VMChart.from_csv(vm_chart)
    if n_per_method not in SPEED_FACTOR_METHODS:
        raise InputError(f"n_per_method: {n_per_method!r} is not one of {', '.join(SPEED_FACTOR_METHODS)}")
    if viscosity_at not in VISCOSITY_AT:
        raise InputError(f"viscosity_at: {viscosity_at!r} is not one of {', '.join(VISCOSITY_AT)}")
    if decimal not in (".", ","):
        raise InputError(f"decimal: {decimal!r} is not one of '.', ','")
    refuse_result_columns(table)  # a designer's 'status' column would be replaced by calc's
    converted = to_catalogue_units(table, units=units, cell=cell, decimal=decimal)
    frame = with_bearing_groups(converted.frame)  # rows alike in every bearing input: one bearing
    if n_per_method != DEFAULT_SPEED_FACTOR_METHOD:  # the table's default for blank n_per_method cells
        frame = frame.assign(n_per_method=blanks_filled(frame, "n_per_method", n_per_method))
    if viscosity_at != DEFAULT_VISCOSITY_AT:  # the table's default for blank viscosity_at cells
        frame = frame.assign(viscosity_at=blanks_filled(frame, "viscosity_at", viscosity_at))
    frame, fill_problems, from_table = fill_from_catalogue(frame, converted.labels)
    vm_read = None
    if vm_chart is not None:  # SKF model: a blank VM of an oil bath from the digitised diagram
        frame, vm_problems, vm_read = fill_vm_from_chart(frame, vm_chart, row_model_names(frame, model) == SKF.name)
        fill_problems = fill_problems + vm_problems
    extra_problems = [p for p in fill_problems if p[1] == "warning"]
    for ext in EXTENSIONS.values():
        with np.errstate(all="ignore"):  # rows in error are computed too, and masked afterwards
            frame, problems = ext.prepare(frame)
        extra_problems.extend(problems)
    require_columns(frame)
    positions = frame.reset_index(drop=True)
    results = compute_supports(positions, f2_chart=f2_chart, labels=converted.labels, model=model)
    for ext in EXTENSIONS.values():
        if ext.settle is not None:
            with np.errstate(all="ignore"):
                positions, results, problems = ext.settle(positions, results, f2_chart=f2_chart,
                                                          labels=converted.labels, model=model)
            extra_problems.extend(problems)
    frame = positions.set_axis(frame.index)
    results.index = table.index
    # the cell's own fault leads, before the model's message; an unknown designation without dimensions (why the
    # model's inputs are missing) leads before that
    cite = converted.labels.cite  # (a workbook's messages name the cell of the column they begin with)
    _add_messages(results, [(i, "error", m, True) for i, errors in _flagged(converted.errors_by_row)
                            for m in reversed(errors)]
                  + [(i, "warning", m, False) for i, warnings in _flagged(converted.warnings_by_row) for m in warnings]
                  + [(i, level, cite(m, i), True) for i, level, m in fill_problems if level == "error"]
                  + [(i, level, cite(m, i), False) for i, level, m in
                     extra_problems + implausible_relations(frame, converted.labels, from_table)])
    # a load below the bearing's minimum load, on the rows that are no errors now (the SKF model's rows have its own)
    _add_messages(results, [(i, level, cite(m, i), False)
                            for i, level, m in minimum_load_relations(frame, results, converted.labels, model)])
    if effects is not None:  # a row of another model is refused, a row outside the fitted domain warned
        _add_messages(results, [(i, level, cite(m, i), level == "error")
                                for i, level, m in effects.apply(frame, results, model=model)])
    extension_columns: dict[str, tuple[pd.DataFrame, dict[str, str]]] = {}
    for ext in EXTENSIONS.values():
        with np.errstate(all="ignore"):  # rows in error are computed too, and masked afterwards
            columns, problems = ext.extend(frame, results, f2_chart=f2_chart, labels=converted.labels, model=model)
        _add_messages(results, [(i, level, cite(m, i), False) for i, level, m in problems])
        extension_columns[ext.owner] = (columns, output_units(owner=ext.owner))
    if vm_read is not None and not np.isnan(vm_read).all():
        extension_columns[SKF.name] = (pd.DataFrame({"VM_chart": vm_read}, index=results.index), {"VM_chart": "1"})
    return ComputedTable(frame, results, extension_columns)


def _flagged(row_messages: dict[int, list[str]]):
    """(position, messages) of the rows that have messages, in row order."""
    return ((i, row_messages[i]) for i in sorted(row_messages) if row_messages[i])


#: a table gets its messages as Python texts (an object column) where there is one for at least every this many
#: rows; fewer are written into the message categorical by their codes
_MANY_MESSAGES = 8


def _add_messages(results: pd.DataFrame, items: list[tuple[int, str, str, bool]]) -> None:
    """Add (row position, 'error' | 'warning', message, first) to the rows' messages in order: ``first`` puts
    a message before the row's message so far. An error makes its row 'error' with NaN results, a warning
    makes an 'ok' row 'warning'. One pass over the messages; the columns are written once: the status by its
    codes, the messages by theirs where few rows get one, else as an object column of Python texts."""
    if not items:
        return
    before = status_codes(results["status"])
    status = before.copy()
    positions = np.fromiter((item[0] for item in items), dtype=np.intp, count=len(items))
    # an error makes its row 'error', a warning an 'ok' row 'warning': the highest level of each row wins
    np.maximum.at(status, positions, np.array([ERROR if item[1] == "error" else WARNING for item in items],
                                              dtype=status.dtype))
    cells = results["message"].array
    if isinstance(cells, pd.Categorical) and len(items) * _MANY_MESSAGES < len(results):
        touched = pd.unique(positions)  # (hashed, not sorted: a dict of them is all the loop needs)
        texts = dict(zip(touched.tolist(), _texts_of_codes(cells)[cells.codes[touched]].tolist()))
        for position, _, message, first in items:
            texts[position] = _joined(texts[position], message, first)
        results["message"] = pd.Series(with_texts(cells, texts.keys(), texts.values()), index=results.index,
                                       copy=False)
    else:  # messages on many rows: Python texts in an object column (hashing them all costs more than it saves)
        column = (_texts_of_codes(cells)[cells.codes] if isinstance(cells, pd.Categorical)
                  else np.asarray(cells, dtype=object).copy())
        for position, _, message, first in items:
            column[position] = _joined(column[position], message, first)
        results["message"] = pd.Series(column, index=results.index, dtype=object, copy=False)
    newly_failed = (status == ERROR) & (before != ERROR)
    results["status"] = pd.Series(status_column(status), index=results.index, copy=False)
    if newly_failed.any():
        results.loc[newly_failed, list(RESULT_UNITS)] = np.nan


def _texts_of_codes(cells: pd.Categorical) -> np.ndarray:
    """The texts of a message categorical by code, '' appended for code -1 (a missing message: none)."""
    return np.append(cells.categories.to_numpy(dtype=object), "")


def _joined(now: str, message: str, first: bool) -> str:
    """A row's message so far, ``now``, with ``message`` put before it (``first``) or after it."""
    return (f"{message}; {now}" if first else f"{now}; {message}") if now else message


def _assemble(table: pd.DataFrame, results: pd.DataFrame, extension_columns) -> pd.DataFrame:
    """The input columns followed by the result columns (a result header the input has replaces its values in
    place, as does a result whose input column is headed another way, ``f0 [1]``, under the result's header:
    :func:`results_spelled_otherwise`); the columns are collected first and joined in one step."""
    written: dict[str, np.ndarray] = {}
    for name, unit in RESULT_UNITS.items():
        written[output_header(name, unit)] = results[name].to_numpy()
    for name, unit in {**M2_REPORT_UNITS, **PLAIN_REPORT_UNITS, **MODEL_REPORT_UNITS}.items():
        if name in results.columns:
            written[output_header(name, unit)] = results[name].to_numpy()
    failed = failed_rows(results)
    for columns, units in extension_columns:
        for name in columns.columns:
            values = columns[name].array if isinstance(columns[name].dtype, pd.CategoricalDtype) \
                else columns[name].to_numpy()
            if values.dtype.kind == "f":
                values = np.where(failed, np.nan, values)
            written[output_header(name, units.get(name, ""))] = values
    _refuse_non_finite(written, results, failed)
    for name in ("status", "message"):  # categoricals, or a message column of Python texts (_add_messages)
        column = results[name]
        categorical = isinstance(column.dtype, pd.CategoricalDtype)
        written[name] = column.array if categorical else column.to_numpy(dtype=object)
    # the caller's frame holds the arrays as they are (no copy into one block); a read-only view of calc's
    # internal frames is copied, so that the caller can change the cells
    columns_out = {header: _text(values) if isinstance(values, pd.Categorical) or values.dtype == object
                   else values if values.flags.writeable else values.copy() for header, values in written.items()}
    spelled = results_spelled_otherwise(table.columns, columns_out)
    if spelled:
        table = table.rename(columns=spelled)
    fresh = {header: values for header, values in columns_out.items() if header not in table.columns}
    out = pd.concat([table, pd.DataFrame(fresh, index=table.index, copy=False)], axis=1)
    for header in columns_out.keys() - fresh.keys():
        out[header] = columns_out[header]
    return out


def _text(values: np.ndarray | pd.Categorical) -> np.ndarray | pd.api.extensions.ExtensionArray:
    """A text result (object array or categorical) as the column pandas makes of text, built by pyarrow from the
    cells (a categorical from its codes): a third of the time of pandas' own conversion (a sixth for a
    categorical). Object cells stay as they are where pandas keeps text as objects (pandas 2) or a cell is no
    text."""
    if TEXT_DTYPE == object:
        return np.asarray(values, dtype=object)
    try:
        if isinstance(values, pd.Categorical):
            codes = values.codes
            if len(codes) and codes[0] >= 0 and isinstance(values.categories[codes[0]], str) \
                    and (codes == codes[0]).all():  # one text in every row ('ok', '')
                return pd.array(_one_text(values.categories[codes[0]], len(codes)), dtype=TEXT_DTYPE)
            dictionary = pa.array(values.categories.to_numpy(dtype=object), type=pa.large_string())
            arrow = pa.DictionaryArray.from_arrays(pa.array(values.codes, mask=values.codes < 0), dictionary)
            return pd.array(arrow.cast(pa.large_string()), dtype=TEXT_DTYPE)
        return pd.array(pa.array(values, type=pa.large_string(), from_pandas=True), dtype=TEXT_DTYPE)
    except (pa.ArrowInvalid, pa.ArrowTypeError):
        return np.asarray(values, dtype=object)


def _one_text(text: str, size: int) -> pa.LargeStringArray:
    """``text`` in each of ``size`` cells, as Arrow writes a text column: offsets that step by the text's length
    in bytes and the text repeated (a tenth of the time of casting a dictionary column, 1 against 12 ms for 10^6
    rows of 'ok')."""
    encoded = text.encode()
    width = len(encoded)
    offsets = (np.arange(0, (size + 1) * width, width, dtype=np.int64) if width
               else np.zeros(size + 1, dtype=np.int64))
    return pa.LargeStringArray.from_buffers(size, pa.py_buffer(offsets), pa.py_buffer(encoded * size))


def _refuse_non_finite(written: dict[str, np.ndarray], results: pd.DataFrame, failed: np.ndarray) -> None:
    """No result leaves calc as inf, nor MR/NR as NaN, on a row not in error (``failed``): such a row becomes
    one (its numeric results NaN in ``written``, the message in ``results``)."""
    numeric = [header for header, values in written.items() if values.dtype.kind == "f"]
    bad: dict[int, str] = {}
    computed = ~failed
    for header in numeric:
        infinite = np.isinf(written[header])
        if infinite.any():  # (one pass where, as usual, no row is)
            for i in np.flatnonzero(infinite & computed):
                bad.setdefault(int(i), header)
    for header in (output_header("MR"), output_header("NR")):
        for i in np.flatnonzero(np.isnan(written[header]) & computed):
            bad.setdefault(int(i), header)
    _add_messages(results, [(i, "error", f"{header}: the result is not a finite number for these inputs; "
                                         "check their magnitudes and units", False) for i, header in sorted(bad.items())])
    if bad:
        rows = np.zeros(len(results), dtype=bool)
        rows[sorted(bad)] = True
        for header in numeric:
            written[header] = np.where(rows, np.nan, written[header])
