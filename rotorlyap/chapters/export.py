"""Figure data as CSV files, for the download link under each figure of the book.

:func:`figure_csv` writes the arrays a figure is drawn from (a figure-data dataclass of
:mod:`rotorlyap.chapters.algorithm`, a mapping of names to values, or a list of named columns) as
one CSV file with a header line. Two layouts, chosen automatically unless ``layout=`` says:

**Wide** (one column per field), when every field is a scalar or a 1-D array and all 1-D
arrays have the same length ``n``: a header of the field names, then ``n`` rows; a scalar field
is repeated on every row. Example, ``{"psi": [0, 1], "A": 0.4}``::

    psi,A
    0,0.4
    1,0.4

**Long** (one row per number) otherwise, when fields have several dimensions, different
lengths or are ragged: the header is ``field,i0,i1,...,value`` with as many index columns as
the deepest field needs, and each number is one row giving its field name, its indices and
its value; unused index columns are empty.

* a scalar field has no index: ``A,,,0.4`` in a file with two index columns;
* a 1-D field of length ``n`` has one index, ``i0 = 0 .. n-1``;
* a 2-D field of shape ``(n, m)`` has two, ``i0`` (row) and ``i1`` (column), in row-major order,
  and so on for more dimensions;
* a ragged field, a tuple or list of arrays of different shapes (motions of different
  lengths, one item per panel, ...), uses its first index for the item and the following ones
  for the item's own indices: the ``k``-th point of the second motion of ``outside`` is
  ``outside,1,k,0,<y>`` and ``outside,1,k,1,<y'>``.

In Python, ``pandas.read_csv(path)`` then ``df[df.field == "norm"]`` gives back one field of a
long file. Numbers are written with ``%.6g`` (six significant digits; ``nan``, ``inf``),
integers exactly, booleans as ``1``/``0``, strings as they are; the same data always gives
the same bytes. Lines end with ``\\n``.
"""

from __future__ import annotations

import csv
import dataclasses
import io
import numbers
import os
import tempfile
from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np

__all__ = ["figure_csv", "format_value", "glue_facts", "markdown_table"]


def format_value(value) -> str:
    """Format one number (or string) the way :func:`figure_csv` writes it.

    Booleans become ``1``/``0``, integers are written exactly, other real numbers with
    ``%.6g``, strings unchanged.

    Raises
    ------
    TypeError
        For anything else (complex numbers, ``None``, objects).
    """
    if isinstance(value, (bool, np.bool_)):
        return "1" if value else "0"
    if isinstance(value, (numbers.Integral, np.integer)):
        return str(int(value))
    if isinstance(value, (numbers.Real, np.floating)):
        return "%.6g" % float(value)
    if isinstance(value, str):
        return value
    raise TypeError(f"cannot write {type(value).__name__} {value!r} to a figure CSV")


def _is_scalar(value) -> bool:
    return isinstance(value, (numbers.Real, np.bool_, np.number, str)) and not isinstance(value, complex)


def _leaf_array(value, name: str) -> np.ndarray:
    arr = np.asarray(value)
    if arr.dtype.kind == "c":
        raise TypeError(f"field {name!r}: complex values are not supported")
    if arr.dtype.kind not in "biufUSO":
        raise TypeError(f"field {name!r}: cannot write an array of dtype {arr.dtype}")
    return arr


def _node(value, name: str):
    """Normalise a field to ('leaf', ndarray) or ('seq', [nodes])."""
    if isinstance(value, np.ndarray):
        return ("leaf", _leaf_array(value, name))
    if _is_scalar(value):
        return ("leaf", np.asarray(value, dtype=object))
    if isinstance(value, (list, tuple)):
        if all(_is_scalar(v) for v in value):
            arr = np.empty(len(value), dtype=object)
            arr[:] = list(value)
            return ("leaf", arr)
        return ("seq", [_node(v, name) for v in value])
    raise TypeError(
        f"field {name!r}: cannot write {type(value).__name__} to a figure CSV "
        "(expected a number, a string, an array or a list/tuple of them)"
    )


def _fields(data) -> list[tuple[str, object]]:
    """The (name, value) pairs of the accepted inputs, in their natural order."""
    if dataclasses.is_dataclass(data) and not isinstance(data, type):
        return [(f.name, getattr(data, f.name)) for f in dataclasses.fields(data)]
    if isinstance(data, Mapping):
        pairs = list(data.items())
    elif isinstance(data, Sequence) and not isinstance(data, (str, bytes)) and len(data) > 0:
        items = list(data)
        if all(dataclasses.is_dataclass(d) and not isinstance(d, type) for d in items):
            kinds = {type(d) for d in items}
            if len(kinds) != 1:
                raise TypeError("a sequence of figure-data objects must hold one dataclass type")
            names = [f.name for f in dataclasses.fields(items[0])]
            return [(n, tuple(getattr(d, n) for d in items)) for n in names]
        if not all(isinstance(p, (tuple, list)) and len(p) == 2 for p in items):
            raise TypeError("a list of columns must hold (name, values) pairs")
        pairs = [tuple(p) for p in items]
    else:
        raise TypeError(
            f"cannot write {type(data).__name__} as figure data: expected a dataclass "
            "instance, a sequence of them, a mapping of names to values or a list of "
            "(name, values) pairs"
        )
    if not pairs:
        raise ValueError("figure data has no fields")
    names = [n for n, _ in pairs]
    for n in names:
        if not isinstance(n, str) or not n:
            raise TypeError(f"field names must be non-empty strings, got {n!r}")
    if len(set(names)) != len(names):
        raise ValueError(f"duplicate field names in {names}")
    return pairs


def _depth(node) -> int:
    kind, content = node
    if kind == "leaf":
        return content.ndim
    return 1 + max((_depth(c) for c in content), default=0)


def _long_rows(name: str, node, prefix: tuple):
    kind, content = node
    if kind == "seq":
        for i, child in enumerate(content):
            yield from _long_rows(name, child, prefix + (i,))
        return
    for idx in np.ndindex(content.shape):
        yield name, prefix + idx, content[idx]


def _wide_length(nodes) -> int | None:
    """Number of rows if the fields fit the wide layout (1 if all are scalars), else None."""
    lengths = set()
    for kind, content in nodes:
        if kind != "leaf" or content.ndim > 1:
            return None
        if content.ndim == 1:
            lengths.add(content.shape[0])
    if len(lengths) > 1:
        return None
    return lengths.pop() if lengths else 1


def _table(data, layout: str) -> tuple[list[str], list[list[str]]]:
    pairs = _fields(data)
    names = [n for n, _ in pairs]
    nodes = [_node(v, n) for n, v in pairs]
    if layout not in ("auto", "wide", "long"):
        raise ValueError(f"layout must be 'auto', 'wide' or 'long', not {layout!r}")
    n = _wide_length(nodes)
    if layout == "wide" and n is None:
        raise ValueError("the wide layout needs every field to be a scalar or a 1-D array of one common length")
    if layout in ("auto", "wide") and n is not None:
        rows = []
        for r in range(n):
            rows.append([format_value(c[r] if c.ndim == 1 else c[()]) for _, c in nodes])
        return names, rows
    depth = max(_depth(node) for node in nodes)
    header = ["field", *(f"i{k}" for k in range(depth)), "value"]
    rows = []
    for name, node in zip(names, nodes):
        for field, idx, value in _long_rows(name, node, ()):
            cells = [str(i) for i in idx] + [""] * (depth - len(idx))
            rows.append([field, *cells, format_value(value)])
    return header, rows


def figure_csv(data, path: str | os.PathLike, *, layout: str = "auto") -> Path:
    """Write the data of a figure as a CSV file with a header line; return ``Path(path)``.

    Parameters
    ----------
    data : dataclass instance, sequence of dataclass instances, mapping or list of pairs
        What the figure is drawn from: a figure-data dataclass (its fields in declaration
        order), several of one type (one per panel: each field becomes a ragged field whose
        first index is the panel), a mapping ``{name: value}`` or a list of
        ``(name, value)`` columns. Values are numbers, strings, arrays, or lists/tuples of
        them.
    path : str or path-like
        The CSV file to write; missing parent directories are created. The file is written
        to a temporary name and renamed, so a reader never sees half a file.
    layout : {"auto", "wide", "long"}
        ``"auto"`` (default) takes the wide layout when the fields allow it, the long one
        otherwise; see the module documentation for both.

    Returns
    -------
    pathlib.Path
        ``path`` as given (a relative path stays relative), so printing it is reproducible.

    Raises
    ------
    TypeError
        For data or values that have no CSV form (complex numbers, ``None``, objects).
    ValueError
        For an empty or duplicated field name, or ``layout="wide"`` on data that needs the
        long layout.
    """
    header, rows = _table(data, layout)
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(header)
    writer.writerows(rows)
    out = Path(path)
    out.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{out.name}.", suffix=".tmp", dir=out.parent)
    try:
        with os.fdopen(fd, "w", encoding="utf-8", newline="") as fh:
            fh.write(buf.getvalue())
        os.chmod(tmp, 0o644)  # mkstemp makes 0600; the book serves this file
        os.replace(tmp, out)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise
    return out


def glue_facts(facts: Mapping) -> None:
    """Glue every ``name: value`` of ``facts`` for the book's text (myst-nb ``glue``, not displayed).

    The numbers a chapter quotes come from a data object's ``facts()`` method, rounded there to
    the digits the computation determines; one call glues them all, in order. A float rounded to
    a whole number of at least 10 (``round(x)`` gives ``-21096.0``) is glued as an integer, so the
    text does not show a decimal the rounding did not keep (:func:`glue_value`); to show trailing
    zeros that are significant (``0.600``) a fact is a :class:`rotorlyap.reporting.Rounded`.
    """
    from myst_nb import glue

    for name, value in facts.items():
        glue(name, glue_value(value), display=False)


def glue_value(value):
    """What :func:`glue_facts` glues for ``value``: an integer for a whole float (not a
    :class:`~rotorlyap.reporting.Rounded`) of magnitude at least 10, else ``value`` itself."""
    if type(value) in (float, np.float64) and np.isfinite(value) and value == round(value) and abs(value) >= 10:
        return int(value)
    return value


def markdown_table(header: Sequence[str], rows: Sequence[Sequence], *, fmt=str) -> str:
    """A Markdown pipe table from a header and rows (``|`` in cells escaped, newlines joined).

    Cells that are not strings are written with ``fmt`` (default ``str``).
    """
    def cell(v) -> str:
        return (v if isinstance(v, str) else fmt(v)).replace("|", "\\|").replace("\n", " ")

    lines = ["| " + " | ".join(cell(h) for h in header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(cell(v) for v in row) + " |" for row in rows]
    return "\n".join(lines)
