"""The pages and text of a PDF printed by Chromium, read with the standard library only.

Enough of the PDF format for the book's PDF (``tools/make_pdf.py``): the cross-reference
table, indirect objects, Flate-compressed streams, the page tree, and text drawn with fonts
that carry a ``/ToUnicode`` map (Chromium's Skia writes every text font so, as Type0 fonts with
two-byte codes). Text in fonts without a map (Skia's Type3 glyph fonts, MathJax's symbols) is
not decoded. Not a general PDF reader: a file it cannot read raises :class:`PdfError`, saying
what it met.
"""

from __future__ import annotations

import re
import zlib
from pathlib import Path


class PdfError(ValueError):
    """A file this reader cannot read as a PDF."""


_REF = re.compile(rb"(\d+)\s+(\d+)\s+R")


class Pdf:
    """A PDF file's objects, pages and text.

    Parameters
    ----------
    path : Path
        The file.
    """

    def __init__(self, path: Path):
        self.data = Path(path).read_bytes()
        if not self.data.startswith(b"%PDF-"):
            raise PdfError(f"{path} does not start with %PDF-")
        self.offsets = self._xref()
        self._cache: dict[int, tuple[bytes, bytes | None]] = {}

    # -- objects -------------------------------------------------------------------------
    def _xref(self) -> dict[int, int]:
        m = None
        for m in re.finditer(rb"startxref\s+(\d+)", self.data):
            pass
        if m is None:
            raise PdfError("no startxref")
        pos = int(m.group(1))
        offsets: dict[int, int] = {}
        while True:
            if not self.data.startswith(b"xref", pos):
                raise PdfError("no classic cross-reference table at %d (cross-reference streams "
                               "are not read)" % pos)
            pos += 4
            trailer = self.data.find(b"trailer", pos)
            body = self.data[pos:trailer].split(b"\n")
            start = count = None
            for line in body:
                parts = line.split()
                if len(parts) == 2:
                    start, count = int(parts[0]), 0
                elif len(parts) == 3 and start is not None:
                    if parts[2] == b"n":
                        offsets.setdefault(start + count, int(parts[0]))
                    count += 1
            tail = self.data[trailer:trailer + 2000]
            if not hasattr(self, "trailer"):
                self.trailer = tail
            prev = re.search(rb"/Prev\s+(\d+)", tail.split(b"startxref")[0])
            if not prev:
                return offsets
            pos = int(prev.group(1))

    def obj(self, num: int) -> tuple[bytes, bytes | None]:
        """Object ``num``: its text (a dictionary, array, number...) and, for a stream, its
        decoded data."""
        if num in self._cache:
            return self._cache[num]
        if num not in self.offsets:
            raise PdfError(f"object {num} is not in the cross-reference table")
        pos = self.offsets[num]
        head = re.compile(rb"\s*%d\s+\d+\s+obj" % num).match(self.data, pos)
        if not head:
            raise PdfError(f"object {num} not found at offset {pos}")
        pos = head.end()
        end = self.data.find(b"endobj", pos)
        s = self.data.find(b"stream", pos, end)
        if s < 0:
            out = (self.data[pos:end].strip(), None)
        else:
            text = self.data[pos:s]
            length = self._value(text, b"Length")
            n = int(self._resolve(length)[0]) if length else None
            start = s + len(b"stream")
            start += 2 if self.data[start:start + 2] == b"\r\n" else 1
            raw = self.data[start:start + n] if n is not None else self.data[start:self.data.find(b"endstream", start)]
            if b"/FlateDecode" in text:
                try:
                    raw = zlib.decompress(raw)
                except zlib.error as exc:
                    raise PdfError(f"object {num}: bad Flate stream ({exc})") from exc
            elif b"/Filter" in text:
                raw = None  # images (DCT) and other filters: not needed for text
            out = (text.strip(), raw)
        self._cache[num] = out
        return out

    def _resolve(self, value: bytes) -> tuple[bytes, bytes | None]:
        m = _REF.fullmatch(value.strip())
        return self.obj(int(m.group(1))) if m else (value, None)

    @staticmethod
    def _value(text: bytes, key: bytes) -> bytes | None:
        """The value of ``/key`` in a dictionary's text: a reference, a name, a number, or a
        bracketed array / nested dictionary."""
        m = re.search(rb"/" + key + rb"(?![A-Za-z0-9])\s*", text)
        if not m:
            return None
        rest = text[m.end():]
        ref = re.match(rb"\d+\s+\d+\s+R", rest)
        if ref:
            return ref.group(0)
        if rest[:2] == b"<<" or rest[:1] == b"[":
            opener, closer = (b"<<", b">>") if rest[:2] == b"<<" else (b"[", b"]")
            depth, i = 0, 0
            while i < len(rest):
                if rest.startswith(opener, i):
                    depth += 1
                    i += len(opener)
                elif rest.startswith(closer, i):
                    depth -= 1
                    i += len(closer)
                    if depth == 0:
                        return rest[:i]
                else:
                    i += 1
            raise PdfError(f"unbalanced /{key.decode()} value")
        tok = re.match(rb"[^\s/<>\[\]()]+|/[^\s/<>\[\]()]+", rest)
        return tok.group(0) if tok else None

    def _dict(self, value: bytes | None) -> bytes:
        if value is None:
            return b""
        text, _ = self._resolve(value)
        return text

    # -- pages ---------------------------------------------------------------------------
    def pages(self) -> list[bytes]:
        """The page dictionaries, in order (the page tree walked from the catalogue)."""
        root = self._value(self.trailer, b"Root")
        if root is None:
            raise PdfError("no /Root in the trailer")
        catalog = self._dict(root)
        out: list[bytes] = []

        def walk(ref: bytes, depth: int = 0) -> None:
            if depth > 50:
                raise PdfError("page tree deeper than 50")
            node = self._dict(ref)
            if re.search(rb"/Type\s*/Pages\b", node):
                kids = self._value(node, b"Kids") or b"[]"
                for m in _REF.finditer(self._dict(kids) if _REF.fullmatch(kids) else kids):
                    walk(m.group(0), depth + 1)
            else:
                out.append(node)

        walk(self._value(catalog, b"Pages"))
        return out

    def page_count(self) -> int:
        return len(self.pages())

    # -- text ----------------------------------------------------------------------------
    def _cmap(self, font_ref: bytes) -> tuple[dict[bytes, str], int]:
        font = self._dict(font_ref)
        tu = self._value(font, b"ToUnicode")
        if tu is None:
            return {}, 1
        _, data = self._resolve(tu)
        data = data or b""
        width = 2
        cs = re.search(rb"begincodespacerange\s*<([0-9A-Fa-f]+)>", data)
        if cs:
            width = len(cs.group(1)) // 2
        table: dict[bytes, str] = {}
        for block in re.findall(rb"beginbfchar(.*?)endbfchar", data, re.S):
            for src, dst in re.findall(rb"<([0-9A-Fa-f]+)>\s*<([0-9A-Fa-f]*)>", block):
                table[bytes.fromhex(src.decode())] = _utf16(dst)
        for block in re.findall(rb"beginbfrange(.*?)endbfrange", data, re.S):
            for lo, hi, dst in re.findall(rb"<([0-9A-Fa-f]+)>\s*<([0-9A-Fa-f]+)>\s*(<[0-9A-Fa-f]*>|\[[^\]]*\])", block):
                a, b = int(lo, 16), int(hi, 16)
                n = len(lo) // 2
                if dst.startswith(b"["):
                    for k, d in enumerate(re.findall(rb"<([0-9A-Fa-f]*)>", dst)):
                        table[(a + k).to_bytes(n, "big")] = _utf16(d)
                else:
                    base = _utf16(dst[1:-1])
                    for k in range(b - a + 1):
                        table[(a + k).to_bytes(n, "big")] = base[:-1] + chr(ord(base[-1]) + k) if base else ""
        return table, width

    def page_text(self, page: bytes) -> str:
        """The text of one page, runs separated by spaces (glyphs of fonts without a
        ``/ToUnicode`` map left out)."""
        resources = self._dict(self._value(page, b"Resources"))
        fonts_text = self._dict(self._value(resources, b"Font"))
        fonts = {m.group(1): m.group(2) for m in re.finditer(rb"/([^\s/<>\[\]()]+)\s*(\d+\s+\d+\s+R)", fonts_text)}
        contents = self._value(page, b"Contents")
        if contents is None:
            return ""
        refs = [m.group(0) for m in _REF.finditer(contents)] if contents.startswith(b"[") else [contents]
        stream = b"\n".join((self._resolve(r)[1] or b"") for r in refs)
        maps: dict[bytes, tuple[dict[bytes, str], int]] = {}
        cmap, width = {}, 1
        out: list[str] = []
        token = re.compile(rb"/([^\s/<>\[\]()]+)\s+[-\d.]+\s+Tf|<([0-9A-Fa-f\s]*)>|\(((?:\\.|[^\\)])*)\)|(Td|TD|Tm|T\*|ET)\b", re.S)
        for m in token.finditer(stream):
            if m.group(1) is not None:
                name = m.group(1)
                if name not in maps:
                    maps[name] = self._cmap(fonts[name]) if name in fonts else ({}, 1)
                cmap, width = maps[name]
            elif m.group(2) is not None:
                raw = bytes.fromhex(re.sub(rb"\s", b"", m.group(2)).decode())
                out.append("".join(cmap.get(raw[i:i + width], "") for i in range(0, len(raw), width)))
            elif m.group(3) is not None:
                raw = re.sub(rb"\\(.)", rb"\1", m.group(3))
                out.append("".join(cmap.get(raw[i:i + width], "") for i in range(0, len(raw), width)) if cmap
                           else "")
            else:
                out.append(" ")
        return re.sub(r"\s+", " ", "".join(out)).strip()

    def text(self) -> list[str]:
        """The text of every page, in order."""
        return [self.page_text(p) for p in self.pages()]


def _utf16(hexdigits: bytes) -> str:
    raw = bytes.fromhex(hexdigits.decode())
    return raw.decode("utf-16-be", errors="replace") if raw else ""
