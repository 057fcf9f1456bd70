"""The results sheet as a printed document, and its PDF made by LibreOffice.

A results sheet prints on landscape A4 pages of :data:`SUPPORTS_PER_PAGE`
supports each (scaled to one page wide, with a manual page break every 30
rows; the height is left free, since LibreOffice drops manual breaks when
it scales to a number of pages tall, so a page whose messages take many
lines can spill onto one more), with the header and units rows and the
columns up to the designation repeated on every page (print titles), and a
page header naming the input file and sheet, the bearingheat version and
the date (:class:`PrintSetup`). :func:`export_pdf` prints one sheet of a
workbook to PDF with headless LibreOffice (:mod:`.libreoffice`).

>>> setup = PrintSetup.of("gearbox & co.xlsx", "Supports", supports=65, title_columns=3,
...                       version="1.2.0", date="2025-03-01")
>>> setup.breaks, setup.pages, setup.title_columns
([32, 62], 3, '$A:$C')
>>> setup.header
'&L&"-,Bold"results of gearbox && co.xlsx, sheet Supports&Rbearingheat 1.2.0, 2025-03-01'
"""
from __future__ import annotations

import datetime as _dt
import io
import math
import re
import tempfile
import zipfile
from dataclasses import dataclass
from importlib import metadata
from pathlib import Path

from lxml import etree
from openpyxl.worksheet.pagebreak import Break, RowBreak

from bearingheat.errors import ExcelError
from bearingheat.io.excel.libreoffice import convert, soffice
from bearingheat.io.files import atomic_write, safe_output

__all__ = ["SUPPORTS_PER_PAGE", "PAGE_MARGINS", "PrintSetup", "package_version", "export_pdf", "pdf_output",
           "pdf_page_count", "is_bearingheat_header", "NO_LIBREOFFICE"]

#: supports (data rows) on one printed page
SUPPORTS_PER_PAGE = 30
#: the header and units rows repeat on every page
TITLE_ROWS = "$1:$2"
#: page footer: the page number
FOOTER = "&Cpage &P of &N"
#: page margins [in]: narrow, a wide table needs the width
PAGE_MARGINS = {"left": 0.4, "right": 0.4, "top": 0.6, "bottom": 0.5, "header": 0.25, "footer": 0.25}
#: a page header that starts so is bearingheat's (a second run writes it anew, with the new date)
_HEADER_START = '&L&"-,Bold"results of '
_MAIN = "http://schemas.openxmlformats.org/spreadsheetml/2006/main"
NO_LIBREOFFICE = ("--pdf needs LibreOffice (the program soffice or libreoffice, e.g. the Debian package "
                  "libreoffice-calc-nogui), which is not installed")


def package_version() -> str:
    """The installed bearingheat version ('unknown' when the package metadata is missing)."""
    try:
        return metadata.version("bearingheat")
    except metadata.PackageNotFoundError:
        return "unknown"


def _escape(text: str) -> str:
    """Text in a page header: '&' starts a code there, so a literal one is '&&'."""
    return text.replace("&", "&&")


def is_bearingheat_header(header_footer_xml: str) -> bool:
    """Whether a kept ``<headerFooter>`` element is the one bearingheat wrote (then it is written anew, dated
    today); one the designer edited is theirs."""
    try:
        root = etree.fromstring(header_footer_xml.encode("utf-8"))
    except etree.XMLSyntaxError:
        return False
    headers = [child for child in root if isinstance(child.tag, str) and etree.QName(child).localname == "oddHeader"]
    return bool(headers) and (headers[0].text or "").startswith(_HEADER_START)


@dataclass(frozen=True)
class PrintSetup:
    """How a results sheet prints: the page header, the manual page breaks, the print titles, the page count."""

    header: str
    supports: int
    title_columns: str

    @classmethod
    def of(cls, source_name: str, input_sheet: str, *, supports: int, title_columns: int,
           version: str | None = None, date: str | None = None) -> PrintSetup:
        """The print setup of the results of ``input_sheet`` of the file ``source_name`` ('' for a CSV;
        ``supports`` rows;
        the first ``title_columns`` columns repeat on every page); version and date default to the installed
        package and today."""
        version = package_version() if version is None else version
        date = _dt.date.today().isoformat() if date is None else date
        where = f"{_escape(source_name)}, sheet {_escape(input_sheet)}" if input_sheet else _escape(source_name)
        header = f"{_HEADER_START}{where}&Rbearingheat {_escape(version)}, {date}"
        last = chr(ord("A") + max(1, min(title_columns, 26)) - 1)
        return cls(header, supports, f"$A:${last}")

    @property
    def pages(self) -> int:
        return max(1, math.ceil(self.supports / SUPPORTS_PER_PAGE))

    @property
    def breaks(self) -> list[int]:
        """The last sheet row of every page but the last (rows 1 and 2 are the header and the units)."""
        return [2 + SUPPORTS_PER_PAGE * k for k in range(1, self.pages)]

    def print_titles(self, sheet_ref: str) -> str:
        """The value of the sheet's ``_xlnm.Print_Titles`` name: the title columns and rows."""
        return f"{sheet_ref}!{self.title_columns},{sheet_ref}!{TITLE_ROWS}"

    def xml(self) -> dict[str, str]:
        """The worksheet elements of the setup by name (ECMA-376 Part 1, 18.3.1: pageSetup, headerFooter,
        rowBreaks; sheetPr's pageSetUpPr says fit to pages)."""
        breaks = "".join(f'<brk id="{row}" max="16383" man="1"/>' for row in self.breaks)
        escape = {"&": "&amp;", "<": "&lt;", ">": "&gt;"}
        header = "".join(escape.get(c, c) for c in self.header)
        footer = "".join(escape.get(c, c) for c in FOOTER)
        return {
            "pageMargins": "<pageMargins " + " ".join(f'{k}="{v:g}"' for k, v in PAGE_MARGINS.items()) + "/>",
            "pageSetup": '<pageSetup paperSize="9" orientation="landscape" fitToWidth="1" '
                         'fitToHeight="0"/>',
            "headerFooter": f"<headerFooter><oddHeader>{header}</oddHeader><oddFooter>{footer}</oddFooter>"
                            "</headerFooter>",
            "rowBreaks": f'<rowBreaks count="{len(self.breaks)}" manualBreakCount="{len(self.breaks)}">{breaks}'
                         "</rowBreaks>" if self.breaks else "",
            "pageSetUpPr": '<pageSetUpPr fitToPage="1"/>',
        }

    def apply(self, ws) -> None:
        """The same setup on an openpyxl worksheet (the ``-o`` copy)."""
        ws.page_setup.orientation = "landscape"
        ws.page_setup.paperSize = ws.PAPERSIZE_A4
        ws.page_setup.fitToWidth = 1
        ws.page_setup.fitToHeight = 0
        ws.sheet_properties.pageSetUpPr.fitToPage = True
        for side, inches in PAGE_MARGINS.items():
            setattr(ws.page_margins, side, inches)
        ws.print_title_rows = TITLE_ROWS.replace("$", "")
        ws.print_title_cols = self.title_columns.replace("$", "")
        left, right = self.header[2:].split("&R", 1)
        ws.oddHeader.left.text, ws.oddHeader.right.text = left, right
        ws.oddFooter.center.text = FOOTER[2:]
        ws.row_breaks = RowBreak()
        for row in self.breaks:
            ws.row_breaks.append(Break(id=row))


def _only_sheet_visible(data: bytes, sheet: str) -> bytes:
    """The workbook package with every sheet but ``sheet`` hidden and ``sheet`` active (what LibreOffice prints)."""
    out = io.BytesIO()
    with zipfile.ZipFile(io.BytesIO(data)) as source, zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as target:
        for info in source.infolist():
            content = source.read(info.filename)
            if info.filename == "xl/workbook.xml":
                root = etree.fromstring(content, etree.XMLParser(resolve_entities=False, no_network=True,
                                                                 huge_tree=True))
                sheets = root.findall(f"{{{_MAIN}}}sheets/{{{_MAIN}}}sheet")
                names = [s.get("name") for s in sheets]
                if sheet not in names:
                    raise ExcelError(f"the workbook has no sheet {sheet!r} to print")
                for element in sheets:
                    if element.get("name") == sheet:
                        element.attrib.pop("state", None)
                    else:
                        element.set("state", "hidden")
                for view in root.iter(f"{{{_MAIN}}}workbookView"):
                    view.set("activeTab", str(names.index(sheet)))
                    view.set("firstSheet", str(names.index(sheet)))
                content = etree.tostring(root, xml_declaration=True, encoding="UTF-8", standalone=True)
            target.writestr(info, content)
    return out.getvalue()


def export_pdf(workbook, sheet: str, target) -> Path:
    """Print sheet ``sheet`` of the workbook file ``workbook`` to the PDF ``target`` with LibreOffice.

    The other sheets are hidden in a temporary copy (the workbook is not
    touched); LibreOffice recalculates the formulas on loading and prints
    with the sheet's own print setup. The PDF is written atomically. Raises
    :class:`~bearingheat.errors.ExcelError` naming the missing program when
    LibreOffice is not installed, or LibreOffice's output when it fails.
    """
    if soffice() is None:
        raise ExcelError(NO_LIBREOFFICE)
    target = Path(target)
    with tempfile.TemporaryDirectory(prefix="bearingheat-pdf-") as folder:
        copy = Path(folder) / f"{target.stem}.xlsx"
        copy.write_bytes(_only_sheet_visible(Path(workbook).read_bytes(), sheet))
        try:
            pdf = convert([copy], "pdf", Path(folder) / "pdf")[0]
        except RuntimeError as exc:
            raise ExcelError(f"{target}: LibreOffice could not print the sheet {sheet!r}: {exc}") from exc
        data = pdf.read_bytes()

    def write(temp: Path) -> None:
        temp.write_bytes(data)

    atomic_write(target, write)
    return target


def pdf_output(workbook, *, force: bool, inputs=()) -> Path:
    """The PDF beside a results workbook (results.xlsx -> results.pdf), checked before any work is done:
    LibreOffice is installed, and the file may be written (:func:`bearingheat.io.files.safe_output`: an
    existing one only with ``force``, never an input)."""
    if soffice() is None:
        raise ExcelError(NO_LIBREOFFICE)
    return safe_output(Path(workbook).with_suffix(".pdf"), force=force, inputs=inputs)


def pdf_page_count(path) -> int:
    """The pages of a PDF: its ``/Type /Page`` objects (not ``/Pages``); no PDF library needed."""
    return len(re.findall(rb"/Type\s*/Page(?![a-zA-Z])", Path(path).read_bytes()))
