"""Append bearingheat's cell styles to a workbook's ``xl/styles.xml``, never renumbering what is there.

The results sheet of ``calc --in-place`` is written as XML
(:mod:`.sheetxml`); its cells refer to cell formats (``cellXfs``) by index.
:class:`StyleSheet` finds or appends those formats, with their fonts, fills
and borders, and the named cell styles ("bearingheat result", ...) that the
designer sees in Excel's style gallery. Existing entries keep their index
(ECMA-376 Part 1, 18.8: ``cellXfs``, ``cellStyleXfs``, ``fonts``, ``fills``,
``borders``, ``cellStyles``); an entry equal to one already there is reused,
so a second run adds nothing. A number format that is not built in
(``General`` = 0, ``0`` = 1, ``0.00`` = 2, ``0.0`` is not) is found in
``numFmts`` or appended with the next free id (164 and up); the
differential formats of the conditional formats (``dxfs``) are found or
appended the same way.
"""
from __future__ import annotations

from lxml import etree

from bearingheat.io.excel import style as st

__all__ = ["StyleSheet", "MAIN_NS", "MINIMAL_STYLES"]

MAIN_NS = "http://schemas.openxmlformats.org/spreadsheetml/2006/main"
_M = f"{{{MAIN_NS}}}"
#: the order of the children of <styleSheet> (CT_Stylesheet)
_ORDER = ("numFmts", "fonts", "fills", "borders", "cellStyleXfs", "cellXfs", "cellStyles", "dxfs", "tableStyles",
          "colors", "extLst")
_BUILTIN_FORMATS = {"General": 0, "0": 1, "0.00": 2}
#: the first id of a custom number format (ids below are built in)
_FIRST_CUSTOM_FORMAT = 164
#: a styles part for a workbook that has none: the defaults Excel expects at index 0 (and fill 1)
MINIMAL_STYLES = (
    f'<?xml version="1.0" encoding="UTF-8" standalone="yes"?>\n<styleSheet xmlns="{MAIN_NS}">'
    '<fonts count="1"><font><sz val="11"/><name val="Calibri"/></font></fonts>'
    '<fills count="2"><fill><patternFill patternType="none"/></fill><fill><patternFill patternType="gray125"/>'
    '</fill></fills><borders count="1"><border><left/><right/><top/><bottom/><diagonal/></border></borders>'
    '<cellStyleXfs count="1"><xf numFmtId="0" fontId="0" fillId="0" borderId="0"/></cellStyleXfs>'
    '<cellXfs count="1"><xf numFmtId="0" fontId="0" fillId="0" borderId="0" xfId="0"/></cellXfs>'
    '<cellStyles count="1"><cellStyle name="Normal" xfId="0" builtinId="0"/></cellStyles></styleSheet>'
).encode()
_PARSER = etree.XMLParser(resolve_entities=False, no_network=True, huge_tree=True, remove_blank_text=False)


def _argb(rgb: str | None) -> str | None:
    """openpyxl's '00FFF2CC' (alpha 00) as the opaque 'FFFFF2CC' Excel writes."""
    if not isinstance(rgb, str) or len(rgb) not in (6, 8):
        return None
    return "FF" + rgb[-6:].upper()


def _el(tag: str, attrib: dict | None = None, *children) -> etree._Element:
    element = etree.Element(_M + tag, {k: str(v) for k, v in (attrib or {}).items() if v is not None})
    for child in children:
        if child is not None:
            element.append(child)
    return element


def _font(font) -> etree._Element:
    color = _argb(getattr(font.color, "rgb", None)) if font.color is not None else None
    return _el("font", None,
               _el("b") if font.b else None,
               _el("i") if font.i else None,
               _el("sz", {"val": f"{font.sz:g}"}),
               _el("color", {"rgb": color}) if color else None,
               _el("name", {"val": font.name}),
               _el("family", {"val": 2}))


def _fill(fill) -> etree._Element:
    if fill.patternType is None:
        return _el("fill", None, _el("patternFill", {"patternType": "none"}))
    return _el("fill", None, _el("patternFill", {"patternType": fill.patternType},
                                 _el("fgColor", {"rgb": _argb(fill.fgColor.rgb)}), _el("bgColor", {"indexed": 64})))


def _border(border) -> etree._Element:
    sides = []
    for side_name in ("left", "right", "top", "bottom"):
        side = getattr(border, side_name)
        if side is None or side.style is None:
            sides.append(_el(side_name))
        else:
            color = _argb(getattr(side.color, "rgb", None)) if side.color is not None else None
            sides.append(_el(side_name, {"style": side.style}, _el("color", {"rgb": color}) if color else None))
    return _el("border", None, *sides, _el("diagonal"))


def _alignment(alignment) -> etree._Element | None:
    attrib = {"horizontal": alignment.horizontal, "vertical": alignment.vertical,
              "wrapText": 1 if alignment.wrap_text else None}
    attrib = {k: v for k, v in attrib.items() if v is not None}
    return _el("alignment", attrib) if attrib else None


def _key(element) -> tuple:
    """Comparable content of an element (tag, attributes, children), blind to prefixes and whitespace."""
    if not isinstance(element.tag, str):
        return ("#",)
    attrib = tuple(sorted((etree.QName(k).localname, v) for k, v in element.attrib.items()))
    return (etree.QName(element).localname, attrib, tuple(_key(child) for child in element
                                                          if isinstance(child.tag, str)))


class StyleSheet:
    """``xl/styles.xml`` with bearingheat's cell formats found or appended on demand (:meth:`index`)."""

    def __init__(self, data: bytes | None):
        self.original = data
        self.root = etree.fromstring(data if data is not None else MINIMAL_STYLES, _PARSER)
        self.changed = data is None
        self._cache: dict[tuple[str, bool, str | None], int] = {}
        self._dxf_cache: dict[str, int] = {}
        self._definitions = {s.name: s for s in st._definitions()}

    def _collection(self, name: str) -> etree._Element:
        found = self.root.find(_M + name)
        if found is not None:
            return found
        element = _el(name, {"count": 0})
        position = _ORDER.index(name)
        for index, child in enumerate(self.root):
            if isinstance(child.tag, str) and etree.QName(child).localname in _ORDER[position + 1:]:
                self.root.insert(index, element)
                break
        else:
            self.root.append(element)
        self.changed = True
        return element

    def _find_or_append(self, collection: str, element: etree._Element, *, minimum: int = 0,
                        defaults: tuple = ()) -> int:
        """Index of ``element`` in the collection, appended when absent (after the reserved defaults)."""
        parent = self._collection(collection)
        children = [c for c in parent if isinstance(c.tag, str)]
        key = _key(element)
        for index, child in enumerate(children):
            if index >= minimum and _key(child) == key:
                return index
        for default in defaults[len(children):minimum]:
            parent.append(etree.fromstring(default, _PARSER))
        parent.append(element)
        parent.set("count", str(len([c for c in parent if isinstance(c.tag, str)])))
        self.changed = True
        return len([c for c in parent if isinstance(c.tag, str)]) - 1

    def _named_style(self, name: str, xf_attrib: dict, alignment) -> int:
        """The cellStyleXfs index of the named style ``name`` (added with its cellStyle entry when missing)."""
        styles = self._collection("cellStyles")
        for cell_style in styles:
            if isinstance(cell_style.tag, str) and cell_style.get("name") == name and cell_style.get("xfId"):
                return int(cell_style.get("xfId"))
        base = _el("xf", xf_attrib, alignment)
        index = self._find_or_append("cellStyleXfs", base, minimum=1, defaults=(
            f'<xf xmlns="{MAIN_NS}" numFmtId="0" fontId="0" fillId="0" borderId="0"/>'.encode(),))
        styles.append(_el("cellStyle", {"name": name, "xfId": index}))
        styles.set("count", str(len([c for c in styles if isinstance(c.tag, str)])))
        self.changed = True
        return index

    def number_format_id(self, code: str) -> int:
        """The id of number format ``code``: built in, found in numFmts, or appended with the next free id."""
        if code in _BUILTIN_FORMATS:
            return _BUILTIN_FORMATS[code]
        formats = self._collection("numFmts")
        used = [_FIRST_CUSTOM_FORMAT - 1]
        for element in formats:
            if not isinstance(element.tag, str):
                continue
            if element.get("formatCode") == code:
                return int(element.get("numFmtId"))
            used.append(int(element.get("numFmtId", "0")))
        number = max(used) + 1
        formats.append(_el("numFmt", {"numFmtId": number, "formatCode": code}))
        formats.set("count", str(len([c for c in formats if isinstance(c.tag, str)])))
        self.changed = True
        return number

    def dxf(self, name: str) -> int:
        """The dxfs index of bearingheat's differential format ``name``
        (:data:`bearingheat.io.excel.style.DIFFERENTIAL`)."""
        if name not in self._dxf_cache:
            font = st.DIFFERENTIAL[name]
            color = _argb(getattr(font.color, "rgb", None)) if font.color is not None else None
            element = _el("dxf", None, _el("font", None, _el("b") if font.b else None,
                                           _el("strike") if font.strike else None,
                                           _el("color", {"rgb": color}) if color else None))
            self._dxf_cache[name] = self._find_or_append("dxfs", element)
        return self._dxf_cache[name]

    def index(self, name: str, quote: bool = False, number_format: str | None = None) -> int:
        """The cellXfs index of bearingheat's named style ``name`` (``quote``: with Excel's quote prefix, so
        text such as '=A1' stays text when the cell is edited; ``number_format``: another number format than
        the style's own)."""
        if (name, quote, number_format) in self._cache:
            return self._cache[(name, quote, number_format)]
        definition = self._definitions[name]
        font = self._find_or_append("fonts", _font(definition.font), minimum=1, defaults=(
            f'<font xmlns="{MAIN_NS}"><sz val="11"/><name val="Calibri"/></font>'.encode(),))
        fill = self._find_or_append("fills", _fill(definition.fill), minimum=2, defaults=(
            f'<fill xmlns="{MAIN_NS}"><patternFill patternType="none"/></fill>'.encode(),
            f'<fill xmlns="{MAIN_NS}"><patternFill patternType="gray125"/></fill>'.encode()))
        border = self._find_or_append("borders", _border(definition.border), minimum=1, defaults=(
            f'<border xmlns="{MAIN_NS}"><left/><right/><top/><bottom/><diagonal/></border>'.encode(),))
        style_format = _BUILTIN_FORMATS.get(definition.number_format, 0)
        attrib = {"numFmtId": style_format, "fontId": font, "fillId": fill, "borderId": border,
                  "applyNumberFormat": 1, "applyFont": 1, "applyFill": 1, "applyBorder": 1}
        alignment = _alignment(definition.alignment)
        if alignment is not None:
            attrib["applyAlignment"] = 1
        style_xf = self._named_style(name, attrib, alignment)
        cell_attrib = dict(attrib, xfId=style_xf)
        if number_format is not None:
            cell_attrib["numFmtId"] = self.number_format_id(number_format)
        if quote:
            cell_attrib["quotePrefix"] = 1
        index = self._find_or_append("cellXfs", _el("xf", cell_attrib, _alignment(definition.alignment)),
                                     minimum=1, defaults=(
            f'<xf xmlns="{MAIN_NS}" numFmtId="0" fontId="0" fillId="0" borderId="0" xfId="0"/>'.encode(),))
        self._cache[(name, quote, number_format)] = index
        return index

    def to_bytes(self) -> bytes:
        """The styles part: the original bytes when nothing was appended."""
        if not self.changed and self.original is not None:
            return self.original
        return etree.tostring(self.root, xml_declaration=True, encoding="UTF-8", standalone=True)
