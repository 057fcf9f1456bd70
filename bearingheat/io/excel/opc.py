"""An .xlsx or .xlsm file as an OPC package (ECMA-376 Part 2): read once, refused where an edit cannot keep it
whole, and written back atomically with only the changed parts replaced.

:func:`open_package` reads the file and refuses what no edit may touch
(encrypted, digitally signed, Strict Open XML, a shared workbook with a
change history, a password to modify) with
:class:`~bearingheat.errors.WorkbookContentError`;
:func:`write_package` writes the parts an edit changed and copies every other
part byte for byte, in the same order. The edits themselves are in
:mod:`bearingheat.io.excel.package`.
"""
from __future__ import annotations

import io
import os
import posixpath
import re
import shutil
import zipfile
from dataclasses import dataclass, field
from pathlib import Path
from urllib.parse import unquote

from lxml import etree

from bearingheat.errors import ExcelError, WorkbookContentError
from bearingheat.io.files import WorkbookLock, atomic_write

__all__ = ["Package", "open_package", "write_package", "refusal", "parse_part", "xml_bytes", "rels_part",
           "resolve_target", "office_document", "MAIN", "REL", "PKG_REL", "CT", "WORKSHEET_TYPE", "STYLES_TYPE"]

MAIN = "http://schemas.openxmlformats.org/spreadsheetml/2006/main"
REL = "http://schemas.openxmlformats.org/officeDocument/2006/relationships"
PKG_REL = "http://schemas.openxmlformats.org/package/2006/relationships"
CT = "http://schemas.openxmlformats.org/package/2006/content-types"
STRICT = "http://purl.oclc.org/ooxml/"
WORKSHEET_TYPE = "application/vnd.openxmlformats-officedocument.spreadsheetml.worksheet+xml"
STYLES_TYPE = "application/vnd.openxmlformats-officedocument.spreadsheetml.styles+xml"
_M, _P = f"{{{MAIN}}}", f"{{{PKG_REL}}}"
#: no entities, no network: a workbook's XML is data
_PARSER = etree.XMLParser(resolve_entities=False, no_network=True, huge_tree=True)
_OLE_MAGIC = b"\xd0\xcf\x11\xe0\xa1\xb1\x1a\xe1"


def parse_part(data: bytes, where: str, path: str | os.PathLike[str]) -> etree._Element:
    """The XML of the part ``where`` of the workbook ``path``; :class:`ExcelError` where it is not well-formed."""
    try:
        return etree.fromstring(data, _PARSER)
    except etree.XMLSyntaxError as exc:
        raise ExcelError(f"{path}: damaged workbook, the part {where} cannot be read ({exc})") from exc


def xml_bytes(root: etree._Element) -> bytes:
    """An edited part as bytes, with the XML declaration Office writes."""
    return etree.tostring(root, xml_declaration=True, encoding="UTF-8", standalone=True)


def rels_part(part: str) -> str:
    """The relationships part of ``part``: xl/workbook.xml -> xl/_rels/workbook.xml.rels."""
    folder, name = posixpath.split(part)
    return posixpath.join(folder, "_rels", name + ".rels")


def resolve_target(source: str, target: str) -> str:
    """The part a relationship of ``source`` targets (relative to its folder, or absolute from the root)."""
    target = unquote(target)
    if target.startswith("/"):
        return posixpath.normpath(target.lstrip("/"))
    return posixpath.normpath(posixpath.join(posixpath.dirname(source), target))


def office_document(package_rels: bytes | None, path: str | os.PathLike[str]) -> tuple[str, str] | None:
    """(relationship type, workbook part) of the officeDocument relationship in a package's relationships
    (the bytes of ``_rels/.rels``; ECMA-376 Part 2, 8.3): xl/workbook.xml unless the package names another
    part; None where there is no such relationship (or no ``_rels/.rels``)."""
    if package_rels is None:
        return None
    for relationship in parse_part(package_rels, "_rels/.rels", path).iter(_P + "Relationship"):
        kind = relationship.get("Type", "")
        if kind.endswith("/officeDocument"):
            return kind, resolve_target("", relationship.get("Target", ""))
    return None


def workbook_part(archive: zipfile.ZipFile) -> str:
    """The workbook part of a package read as a zip file (xl/workbook.xml unless its relationships say otherwise:
    :func:`office_document`)."""
    try:
        package_rels: bytes | None = archive.read("_rels/.rels")
    except KeyError:
        package_rels = None
    office = office_document(package_rels, str(archive.filename))
    return "xl/workbook.xml" if office is None else office[1]


@dataclass
class Package:
    """A workbook file read once: its bytes, ZIP members (in order) and the workbook part's name."""

    path: Path
    data: bytes
    infos: list[zipfile.ZipInfo]
    workbook: str
    #: the edit asked for, named in refusals: '--in-place' (calc's results) or 'write_results' (a table)
    action: str = "--in-place"
    _parts: dict[str, bytes] = field(default_factory=dict)

    def names(self) -> list[str]:
        return [info.filename for info in self.infos]

    def find(self, part: str) -> str | None:
        """The member name of ``part`` (OPC part names ignore case), None when absent."""
        wanted = part.lower()
        return next((n for n in self.names() if n.lower() == wanted), None)

    def read(self, part: str) -> bytes | None:
        name = self.find(part)
        if name is None:
            return None
        if name not in self._parts:
            try:
                with zipfile.ZipFile(io.BytesIO(self.data)) as archive:
                    self._parts[name] = archive.read(name)
            except (zipfile.BadZipFile, OSError, EOFError) as exc:
                raise ExcelError(f"{self.path}: damaged workbook, the part {name} cannot be read ({exc})") from exc
        return self._parts[name]

    def required(self, part: str) -> bytes:
        """The bytes of a part the package must have (:func:`open_package` checked it is there)."""
        data = self.read(part)
        if data is None:
            raise ExcelError(f"{self.path}: damaged workbook, the part {part} is missing")
        return data

    def relationships(self, part: str) -> list[etree._Element]:
        data = self.read(rels_part(part))
        return [] if data is None else list(parse_part(data, rels_part(part), self.path).iter(_P + "Relationship"))


#: what to do instead of an edit that is refused, by the action refused
_INSTEAD = {"--in-place": "Write the results to a new workbook with -o OUTPUT.xlsx instead",
            "write_results": "Write the table to a new workbook instead"}


def refusal(path: str | os.PathLike[str], why: str, action: str) -> WorkbookContentError:
    """The refusal of ``action`` ('--in-place' or 'write_results') on the workbook ``path``, and what to do instead."""
    return WorkbookContentError(f"{path}: {action} refused, {why}; the file is unchanged. {_INSTEAD[action]}")


def open_package(path: str | os.PathLike[str], action: str = "--in-place") -> Package:
    """The workbook at ``path`` as a package that :func:`write_results_in_place` or :func:`write_table_in_place`
    can edit, or a refusal.

    :class:`ExcelError` for a file that is not a workbook (or is damaged),
    :class:`WorkbookContentError` for a workbook that cannot be edited
    without losing something (module docstring); its message names
    ``action`` ('--in-place' or 'write_results').
    """
    path = Path(path)
    if action not in _INSTEAD:
        raise ValueError(f"open_package: action {action!r} is not one of {sorted(_INSTEAD)}")
    data = path.read_bytes()
    if data.startswith(_OLE_MAGIC):
        if "EncryptionInfo".encode("utf-16-le") in data:
            raise refusal(path, "the workbook is encrypted (it has a password to open); bearingheat cannot "
                                "edit it without the password", action)
        raise ExcelError(f"{path}: not a readable Excel workbook (an old binary .xls file, not .xlsx)")
    try:
        with zipfile.ZipFile(io.BytesIO(data)) as archive:
            infos = archive.infolist()
    except (zipfile.BadZipFile, OSError, EOFError) as exc:
        raise ExcelError(f"{path}: not a readable Excel workbook ({exc})") from exc
    lowered = [i.filename.lower() for i in infos]
    if len(set(lowered)) != len(lowered):
        raise ExcelError(f"{path}: damaged workbook, a part appears twice in the ZIP file")
    package = Package(path, data, infos, "", action)
    if package.find("[Content_Types].xml") is None or package.find("_rels/.rels") is None:
        raise ExcelError(f"{path}: not a readable Excel workbook (no [Content_Types].xml or _rels/.rels)")
    office = office_document(package.read(rels_part("")), path)
    if office is None:
        raise ExcelError(f"{path}: not a readable Excel workbook (no workbook part)")
    if office[0].startswith(STRICT):
        raise refusal(path, "the workbook is saved as Strict Open XML, which bearingheat does not edit (save it "
                            "in Excel as 'Excel Workbook (*.xlsx)')", action)
    package.workbook = office[1]
    workbook_data = package.read(package.workbook)
    if workbook_data is None:
        raise ExcelError(f"{path}: not a readable Excel workbook (its workbook part {package.workbook} is missing)")
    if any(n.startswith("_xmlsignatures/") for n in lowered):
        raise refusal(path, "the workbook is digitally signed and any change would break its signature", action)
    if any(n.startswith(posixpath.dirname(package.workbook).lower() + "/revisions/") for n in lowered):
        raise refusal(path, "the workbook is a shared workbook with a change history (xl/revisions), which an edit "
                            "outside Excel would not be part of", action)
    root = parse_part(workbook_data, package.workbook, path)
    if root.tag != _M + "workbook":
        raise refusal(path, f"its workbook part is not SpreadsheetML Transitional ({etree.QName(root).namespace})",
                      action)
    sharing = root.find(_M + "fileSharing")
    if sharing is not None and (sharing.get("reservationPassword") or sharing.get("hashValue")):
        raise refusal(path, "the workbook has a password to modify (write reservation), which bearingheat does "
                            "not bypass", action)
    return package


def _zip_info(info: zipfile.ZipInfo, compress_type: int | None = None) -> zipfile.ZipInfo:
    copy = zipfile.ZipInfo(info.filename, info.date_time)
    copy.compress_type = info.compress_type if compress_type is None else compress_type
    copy.external_attr = info.external_attr
    copy.create_system = info.create_system
    copy.comment = info.comment
    copy.file_size = info.file_size
    return copy


def write_package(package: Package, changes: dict[str, bytes], removed: set[str], lock: WorkbookLock | None,
                  target: Path) -> list[str]:
    """Write the edited package to ``target`` (atomically, after the lock's last check); the parts written."""
    members = {part: package.find(part) for part in changes}
    existing = {member: changes[part] for part, member in members.items() if member is not None}
    new = {part: changes[part] for part, member in members.items() if member is None}
    names = package.names()
    sheets = [i for i, n in enumerate(names) if re.search(r"worksheets/[^/]+\.xml$", n)]
    insert_after = sheets[-1] if sheets else len(names) - 1

    def write(temp: Path) -> None:
        with zipfile.ZipFile(io.BytesIO(package.data)) as source, \
                zipfile.ZipFile(temp, "w", zipfile.ZIP_DEFLATED, allowZip64=True) as target:
            target.comment = source.comment
            for index, info in enumerate(package.infos):
                if info.filename in removed:
                    pass
                elif info.filename in existing:
                    target.writestr(_zip_info(info, zipfile.ZIP_DEFLATED), existing[info.filename])
                else:
                    with source.open(info) as src, target.open(_zip_info(info), "w",
                                                               force_zip64=info.file_size >= 1 << 31) as dst:
                        shutil.copyfileobj(src, dst, 1 << 20)
                if index == insert_after:
                    for part, data in new.items():
                        stamp = zipfile.ZipInfo(part, info.date_time if info.date_time[0] >= 1980
                                                else (1980, 1, 1, 0, 0, 0))
                        stamp.compress_type = zipfile.ZIP_DEFLATED
                        target.writestr(stamp, data)
        if lock is not None:
            lock.check_unchanged()

    try:
        atomic_write(target, write)
    except (zipfile.BadZipFile, EOFError) as exc:
        raise ExcelError(f"{package.path}: damaged workbook, a part cannot be read ({exc})") from exc
    return sorted(set(existing) | set(new) | removed)
