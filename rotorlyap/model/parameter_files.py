"""Parameter files: a blade, its hub and its helicopter in a TOML file.

:meth:`BladeParameters.from_file <rotorlyap.model.parameters.BladeParameters.from_file>` reads
one, :meth:`BladeParameters.to_file <rotorlyap.model.parameters.BladeParameters.to_file>` writes
one (each field's unit and source as a comment). The schema, ``rotorlyap.blade/1``:

* ``schema = "rotorlyap.blade/1"`` (required: a file of another kind, or of a later schema, is
  refused rather than misread);
* an optional table ``[about]`` with free text (``name``, ``description``, and a table
  ``sources`` of field name -> citation): kept in the file for the reader, not used;
* one key per field of :class:`~rotorlyap.model.parameters.BladeParameters`, with the field's
  name and SI unit (m, kg, s, rad, N; fractions of chord and of the blade length where the
  field says so; :data:`~rotorlyap.model.parameters.FIELD_INFO` lists them). A field left out
  takes the template's (Table I) value, and the reader warns which blade fields did;
* values: numbers, strings, ``hub_elements`` an array of 5 numbers; a spanwise profile
  (``chord``, ``cg_position``, ``aerodynamic_centre``, ``mass_per_length``) a number or a
  table ``{ r_over_R = [...], values = [...] }``
  (:class:`~rotorlyap.model.parameters.TabulatedProfile`); ``airfoil`` one of the names of
  :data:`rotorlyap.model.parameters.FILE_AIRFOILS` or a table ``{ base = NAME, <field> = value, ... }`` that changes fields of
  a named section (angles in rad, slopes per rad), or a C81 table: ``airfoil = "name.c81"``
  (a string ending in ``.c81``, any case), the file read by :func:`rotorlyap.model.c81.read_c81`
  from a path relative to the parameter file's directory, or ``airfoil = { file = "name.c81",
  thickness_ratio = 0.09, table_size = 72000 }`` with options of
  :class:`~rotorlyap.model.c81.C81Section`. Writing a blade with a C81 section writes its table
  beside the parameter file, under the section's ``file_name`` (its base name: the file it was
  read from) or else ``<parameter file stem>.c81``, and names it; an existing file there is kept
  if it holds the same table and refused if it holds another. A table not on the printed grid of
  a C81 file (4 decimals) is rounded, with a warning. Fields whose value is ``None``
  (``collective``, ``inflow_ratio``, ``wind_point``) are left out.

Every value then passes the same validation as in Python (ranges, unit slips).

This module knows the file format only; :class:`~rotorlyap.model.parameters.BladeParameters`
gives it the fields, the named sections and the profile type, and builds and checks the blade.
"""

from __future__ import annotations

import dataclasses
import math
import tomllib
import warnings
from pathlib import Path
from typing import Any, Callable, Mapping, Sequence

from .c81 import C81Section, read_c81, write_c81
from .compressibility import THICKNESS_RATIO

__all__ = ["C81_OPTIONS", "C81_SUFFIX", "PROFILE_FIELDS", "SCHEMA", "read_file", "write_file"]

#: The ending (any case) that makes a string ``airfoil`` a C81 file name.
C81_SUFFIX: str = ".c81"

#: Options of a C81 section a parameter file may give beside ``file``
#: (:class:`rotorlyap.model.c81.C81Section`).
C81_OPTIONS: tuple[str, ...] = ("table_size", "thickness_ratio")

#: The schema name and version a parameter file must declare.
SCHEMA: str = "rotorlyap.blade/1"

#: The spanwise profiles, which a file may give as tables.
PROFILE_FIELDS: tuple[str, ...] = ("chord", "cg_position", "aerodynamic_centre", "mass_per_length")


def _fail(path: Path, message: str) -> ValueError:
    return ValueError(f"{path}: {message}")


def _is_c81_name(value: Any) -> bool:
    return isinstance(value, str) and value.lower().endswith(C81_SUFFIX)


def _c81_from(path: Path, file: str, options: Mapping[str, Any]) -> C81Section:
    """The C81 section of ``airfoil = "name.c81"`` (or ``{ file = "name.c81", ... }``), the file
    looked for beside the parameter file ``path``."""
    c81 = (path.parent / file)
    if not c81.is_file():
        raise FileNotFoundError(f"{path}: airfoil = {file!r}: no such C81 file {c81} (a C81 file is "
                                f"looked for relative to the parameter file's directory {path.parent})")
    try:
        table = read_c81(c81)
    except ValueError as exc:
        raise _fail(path, f"airfoil = {file!r}: {exc}") from exc
    unknown = sorted(set(options) - set(C81_OPTIONS))
    if unknown:
        raise _fail(path, f"airfoil: unknown key(s) {unknown} of a C81 section; allowed: file, "
                          f"{', '.join(C81_OPTIONS)}")
    try:
        return C81Section(table, file_name=file, **options)
    except (TypeError, ValueError) as exc:
        raise _fail(path, f"airfoil = {file!r}: {exc}") from exc


def _airfoil_from(path: Path, value: Any, airfoils: Mapping[str, Any]) -> Any:
    if _is_c81_name(value):
        return _c81_from(path, value, {})
    if isinstance(value, dict) and "file" in value:
        options = dict(value)
        file = options.pop("file")
        if not _is_c81_name(file):
            raise _fail(path, f"airfoil.file must name a C81 file ending in {C81_SUFFIX!r}, got {file!r}")
        return _c81_from(path, file, options)
    if isinstance(value, str):
        if value not in airfoils:
            raise _fail(path, f"airfoil must be one of {tuple(airfoils)}, a C81 file name ending in "
                              f"{C81_SUFFIX!r} or a table {{ base = NAME, field = value, ... }}, got {value!r}")
        return airfoils[value]
    if isinstance(value, dict):
        changes = dict(value)
        base = changes.pop("base", None)
        if base not in airfoils:
            raise _fail(path, f"airfoil.base must be one of {tuple(airfoils)}, got {base!r}")
        template = airfoils[base]
        allowed = tuple(f.name for f in dataclasses.fields(template) if f.init)
        unknown = sorted(set(changes) - set(allowed))
        if unknown:
            raise _fail(path, f"airfoil: unknown field(s) {unknown} of {type(template).__name__}; "
                              f"allowed: {allowed}")
        try:
            return dataclasses.replace(template, **changes)
        except (TypeError, ValueError) as exc:
            raise _fail(path, f"airfoil: {exc}") from exc
    raise _fail(path, f"airfoil must be a name or a table, got {value!r}")


def _profile_from(path: Path, name: str, value: Any, profile: Callable[..., Any]) -> Any:
    if isinstance(value, dict):
        if set(value) != {"r_over_R", "values"}:
            raise _fail(path, f"{name}: a tabulated profile is {{ r_over_R = [...], values = [...] }}, "
                              f"got the keys {sorted(value)}")
        try:
            return profile(tuple(value["r_over_R"]), tuple(value["values"]))
        except (TypeError, ValueError) as exc:
            raise _fail(path, f"{name}: {exc}") from exc
    return value


def read_file(path: str | Path, field_names: Sequence[str], airfoils: Mapping[str, Any],
              profile: Callable[..., Any]) -> dict[str, Any]:
    """Read a parameter file (schema :data:`SCHEMA`; see the module docstring) into field values.

    Parameters
    ----------
    path : str or pathlib.Path
        A TOML file.
    field_names : sequence of str
        The keys a file may hold (the fields of the parameter class).
    airfoils : mapping
        Named sections for ``airfoil``.
    profile : callable
        ``profile(r_over_R, values)`` builds a tabulated spanwise profile.

    Returns
    -------
    dict
        ``{field: value}`` for the fields the file gives, ready for the constructor (which
        validates them).

    Raises
    ------
    FileNotFoundError
        If there is no such file, or no C81 file the ``airfoil`` names (the message gives the
        path looked for).
    ValueError
        A file that is not TOML, of another schema, with an unknown key, a bad airfoil or a bad
        profile table (the message names the file and the key, and says what is allowed).
    """
    path = Path(path)
    try:
        with path.open("rb") as fh:
            data = tomllib.load(fh)
    except tomllib.TOMLDecodeError as exc:
        raise _fail(path, f"not a valid TOML file: {exc}") from exc
    schema = data.pop("schema", None)
    if schema != SCHEMA:
        raise _fail(path, f'the file must declare schema = "{SCHEMA}" (a rotorlyap blade file), got {schema!r}')
    about = data.pop("about", {})
    if not isinstance(about, dict):
        raise _fail(path, "[about] must be a table of free text")
    unknown = sorted(set(data) - set(field_names))
    if unknown:
        raise _fail(path, f"unknown key(s) {unknown}; allowed: schema, [about] and the fields of "
                          f"BladeParameters: {tuple(field_names)}")
    values = dict(data)
    if "airfoil" in values:
        values["airfoil"] = _airfoil_from(path, values["airfoil"], airfoils)
    for name in PROFILE_FIELDS:
        if name in values:
            values[name] = _profile_from(path, name, values[name], profile)
    if "hub_elements" in values:
        if not isinstance(values["hub_elements"], list):
            raise _fail(path, f"hub_elements must be an array of 5 numbers, got {values['hub_elements']!r}")
        values["hub_elements"] = tuple(values["hub_elements"])
    return values


# ---------------------------------------------------------------------------- writing
def _toml_value(name: str, value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if not math.isfinite(value):
            raise ValueError(f"{name} = {value!r} cannot be written (TOML parameter files hold finite values)")
        return repr(value)  # the shortest string that reads back to the same double
    if isinstance(value, str):
        return '"' + value.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(value, (tuple, list)):
        return "[" + ", ".join(_toml_value(name, v) for v in value) + "]"
    if isinstance(value, dict):
        return "{ " + ", ".join(f"{k} = {_toml_value(f'{name}.{k}', v)}" for k, v in value.items()) + " }"
    raise ValueError(f"{name} = {value!r} cannot be written to a parameter file")


def _c81_to(value: C81Section, path: Path) -> Any:
    """Write the table of ``value`` beside the parameter file ``path`` and return what the
    parameter file holds: the file name, or ``{ file = ..., <option> = ... }`` for options that
    differ from their defaults."""
    name = Path(value.file_name).name if value.file_name else path.stem + C81_SUFFIX
    target = path.parent / name
    text = write_c81(value.table)
    written = read_c81(text)  # the table as the file holds it (rounded to its printed decimals)
    if target.exists():
        try:
            same = read_c81(target) == written
        except (OSError, ValueError):
            same = False
        if not same:
            raise ValueError(f"airfoil: {target} exists and holds another table than the section "
                             f"{value.name!r}; move it, or give the section another file_name "
                             f"(dataclasses.replace(section, file_name=...))")
    else:
        target.write_text(text, encoding="ascii", newline="\n")
    if written != value.table:
        warnings.warn(f"airfoil: the table {value.name!r} written to {target} is rounded to the printed "
                      f"decimals of a C81 file (coefficients within 5e-5, rotorlyap.model.c81.write_c81): "
                      f"the parameter file reads back this rounded table", UserWarning, stacklevel=4)
    options = {}
    if value.table_size != C81Section(value.table).table_size:
        options["table_size"] = value.table_size
    if value.thickness_ratio != THICKNESS_RATIO:
        options["thickness_ratio"] = value.thickness_ratio
    return {"file": name, **options} if options else name


def _airfoil_to(value: Any, airfoils: Mapping[str, Any], path: Path) -> Any:
    if isinstance(value, C81Section):
        return _c81_to(value, path)
    for key, named in airfoils.items():
        if type(value) is type(named) and value == named:
            return key
    for key, named in airfoils.items():
        if type(value) is type(named):
            return {"base": key, **{f.name: getattr(value, f.name) for f in dataclasses.fields(value)
                                    if f.init and getattr(value, f.name) != getattr(named, f.name)}}
    raise ValueError(f"airfoil {value!r} cannot be written to a parameter file: only a section of the type "
                     f"of a named one can (a named section of {tuple(airfoils)} with changed fields)")


def write_file(path: str | Path, entries: Sequence[tuple[str, Any, str]], airfoils: Mapping[str, Any],
               profile_type: type, *, name: str | None = None, sources: Mapping[str, str] | None = None) -> Path:
    """Write a parameter file that :func:`read_file` reads back to the same values.

    Parameters
    ----------
    path : str or pathlib.Path
        The file to write (overwritten).
    entries : sequence of (str, object, str)
        (field, value, comment) in the order to write; ``None`` values are left out.
    airfoils : mapping
        Named sections (an airfoil equal to one is written by its name, another of the same type
        as a table of the fields that differ from the first of its type).
    profile_type : type
        The tabulated-profile class (attributes ``r_over_R`` and ``values``).
    name : str, optional
        The blade's name, written to ``[about]``.
    sources : mapping, optional
        ``{field: citation}``, written to ``[about.sources]``.

    Returns
    -------
    pathlib.Path
        ``path``.

    Raises
    ------
    ValueError
        A value a file cannot hold: a profile given as an arbitrary callable (give a tabulated
        profile), an airfoil of another type, a ``sources`` key that is not a field, or a C81
        section whose file name is taken beside ``path`` by another table.

    Warns
    -----
    UserWarning
        A C81 table rounded by writing it (module docstring).
    """
    path = Path(path)
    names = [e[0] for e in entries]
    lines = [f"# A rotorlyap blade (schema {SCHEMA}): SI units, one key per field of BladeParameters.",
             "# Comments: the unit, and whether the value was given or is the template's.",
             f'schema = "{SCHEMA}"', ""]
    for field, value, comment in entries:
        if value is None:
            continue
        if field == "airfoil":
            value = _airfoil_to(value, airfoils, path)
        elif isinstance(value, profile_type):
            value = {"r_over_R": value.r_over_R, "values": value.values}
        elif callable(value):
            raise ValueError(f"{field} is a callable profile, which a parameter file cannot hold: give it as "
                             f"rotorlyap.model.parameters.TabulatedProfile(r_over_R, values)")
        lines.append(f"{field} = {_toml_value(field, value)}  # {comment}")
    if name is not None or sources:
        lines += ["", "[about]"]
        if name is not None:
            lines.append(f"name = {_toml_value('name', name)}")
        if sources:
            unknown = sorted(set(sources) - set(names))
            if unknown:
                raise ValueError(f"sources: unknown field(s) {unknown}; allowed: {tuple(names)}")
            lines += ["", "[about.sources]"]
            lines += [f"{k} = {_toml_value(k, v)}" for k, v in sources.items()]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path
