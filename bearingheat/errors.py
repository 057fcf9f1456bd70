"""Every error and warning bearingheat raises, with one base class each.

Catch :class:`BearingheatError` to catch anything the package refuses; it is
a :class:`ValueError`, so code that already catches ``ValueError`` keeps
working. Warnings derive from :class:`BearingheatWarning` (a
:class:`UserWarning`), so ``warnings.simplefilter("error", BearingheatWarning)``
turns every one of them into an exception.

The command line maps these types to exit codes (``bearingheat.cli``): a
:class:`BearingheatError` reaching the command line is unusable input, exit 2;
rows that fail inside a table are reported per row and give exit 1.

This module is a leaf: it imports nothing from the package, and any layer
may import it (as scikit-learn's ``exceptions`` module).
"""
from __future__ import annotations

__all__ = [
    "BearingheatError",
    "BearingheatWarning",
    "UnitError",
    "InputError",
    "DesignationError",
    "DutyCycleError",
    "MissingExtraError",
    "CatalogueError",
    "F2ChartError",
    "VMChartError",
    "ModelError",
    "FrictionInputError",
    "HeatBalanceError",
    "ViscosityError",
    "ContactInputError",
    "OutsideMethodError",
    "NoStandardSizeError",
    "BushingInputError",
    "CoastdownError",
    "LabError",
    "AuditError",
    "DiagnoseError",
    "SelectionError",
    "ExcelError",
    "WorkbookContentError",
    "SheetContentError",
    "UsageError",
    "OutputFileError",
    "WorkbookLockedError",
    "WorkbookChangedError",
    "ViscosityRangeWarning",
]


class BearingheatError(ValueError):
    """Base of every error bearingheat raises: input it cannot use, with a message saying why."""


class BearingheatWarning(UserWarning):
    """Base of every warning bearingheat emits."""


class UnitError(BearingheatError):
    """A value has no unit, or a unit of the wrong dimension."""


class InputError(BearingheatError):
    """A table that cannot be used at all: a required column missing, a header unit of the wrong dimension."""


class DesignationError(BearingheatError):
    """A designation, type or series that no catalogue table covers."""


class CatalogueError(BearingheatError):
    """A catalogue table that is missing or malformed (a packaging fault, not the user's input)."""


class F2ChartError(BearingheatError):
    """A user-digitised f2 chart that cannot be used."""


class VMChartError(BearingheatError):
    """A user-digitised chart of the SKF drag loss factor VM that cannot be used."""


class ModelError(BearingheatError):
    """A friction model name that is not in the registry, or a model that cannot run a row."""


class FrictionInputError(BearingheatError):
    """An argument of the unit-aware friction API outside the model's range."""


class HeatBalanceError(BearingheatError):
    """A bearing or an operating point the heat balance cannot be computed for."""


class ViscosityError(BearingheatError):
    """Oil data that fix no viscosity-temperature line: an unknown ISO VG grade, a viscosity index no oil of
    the grade reaches (ASTM D2270), or not exactly one of nu40 and nu100, two points, iso_vg."""


class ContactInputError(BearingheatError):
    """Ball geometry or a load outside the range of the ball contact formulas.

    ``row`` is the Series label or array position of the first bad value (None for a scalar).
    """

    def __init__(self, message: str, row: object = None):
        super().__init__(message)
        self.row = row


class OutsideMethodError(BearingheatError):
    """A plain-bushing duty outside the range of the sizing method."""


class NoStandardSizeError(OutsideMethodError):
    """No standard bushing length or washer diameter is large enough for the duty."""


class BushingInputError(BearingheatError):
    """An argument of the plain-bushing sizing that cannot be used: a load, speed, bore, K or [p] that is not
    positive, an application, shaft, life or load type that the DU/DP bushing handbook does not tabulate, or a table cell lost in
    the source's OCR."""


class CoastdownError(BearingheatError):
    """A run-down record that cannot be analysed."""


class LabError(BearingheatError):
    """A laboratory-rig table that cannot be processed."""


class AuditError(BearingheatError):
    """A measured-torque or reference-speed table that cannot be audited."""


class DiagnoseError(BearingheatError):
    """Measured data that cannot be diagnosed, or a fitted effect that cannot be applied."""


class SelectionError(BearingheatError):
    """An operating point or ranking that choosing a bearing among the candidates cannot use."""


class DutyCycleError(InputError):
    """A duty cycle that cannot be summarised: shares not summing to 1, a negative share, a support whose
    rows name different bearings."""


class MissingExtraError(BearingheatError):
    """A feature needs an optional dependency that is not installed; the message names the extra."""


class ExcelError(InputError):
    """A workbook that cannot be read, or a sheet that cannot be written."""


class WorkbookContentError(ExcelError):
    """A workbook whose content a rewrite would lose; it is refused and left unchanged."""


class SheetContentError(WorkbookContentError):
    """A sheet bearingheat wrote and would replace now holds content of the designer's (charts, notes, tables
    ...) that the replacement would lose; refused whether the results go into the workbook or into a copy.
    ``why`` says what the sheet holds and what to do."""

    def __init__(self, message: str, why: str = ""):
        super().__init__(message)
        self.why = why


class UsageError(BearingheatError):
    """A command-line argument that cannot be used (the command line reports it and exits with code 2)."""


class OutputFileError(BearingheatError):
    """An output file that cannot or must not be written: it exists (and no --force), it is the input, it is
    read-only, its folder is missing or not writable, or the write failed (disk full); the message names the
    file and the cause, and the file is left as it was."""


class WorkbookLockedError(OutputFileError):
    """A workbook that another program holds: Excel's or LibreOffice's lock file sits beside it, or another
    bearingheat run is writing it."""


class WorkbookChangedError(OutputFileError):
    """A workbook that another program saved while bearingheat was reading or working on it; nothing was
    written."""


class ViscosityRangeWarning(BearingheatWarning):
    """A viscosity or temperature outside the range where the viscosity law was checked."""
