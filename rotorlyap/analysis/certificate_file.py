"""Certificates as files anyone can check: :func:`save_certificate`, :func:`read_certificate`, :func:`verify`.

A :class:`~rotorlyap.analysis.certify.Certificate` of the sound rule is written
(:meth:`Certificate.save <rotorlyap.analysis.certify.Certificate.save>`) as one JSON file that
holds everything that defines it, and :func:`verify` (``rotorlyap.verify``, ``rotorlyap verify
FILE``) checks it again from nothing but the file: it rebuilds the blade, the steady motion and
the function from the stored numbers (the function's own coefficients: nothing is designed or
solved again) and checks every claim with the package's own ``W``, ``W'`` and the engine's own
searches. A file whose claims no longer hold after an edit is refused by those checks, never by
a checksum: an edited file whose claims still hold verifies.

The format (``format = "rotorlyap.certificate"``, ``version = 1``), every number in SI units
(rad, rad/rad, s, m, kg, N; the scaled norm is dimensionless), every float written by Python's
``repr`` (the shortest text that reads back to the same double: floats round-trip bit for bit;
NaN and infinities are not allowed), arrays as nested JSON lists:

``package_version``
    The rotorlyap that wrote it (for the reader; not checked).
``blade``
    ``parameters_toml``: the blade's parameter file (:meth:`BladeParameters.to_file
    <rotorlyap.model.parameters.BladeParameters.to_file>`, schema ``rotorlyap.blade/1``) with the
    trimmed controls; ``files``: ``{name: text}`` of the files it names (a C81 airfoil table).
``flight``
    ``mu`` (advance ratio), ``condition`` (:data:`rotorlyap.model.forward_trim.TRIM_TARGETS`),
    ``controls`` (collective, cyclic_cos, cyclic_sin, shaft_tilt in rad; inflow_ratio, or null),
    which must equal the blade's.
``steady_motion``
    ``kind = "constant"`` with ``state`` (6,), or ``kind = "hermite"`` with ``values`` and
    ``slopes`` (n, 6): ``xi`` and ``xi'`` at ``psi_j = 2 pi j / n``, the periodic cubic Hermite
    interpolant of :class:`~rotorlyap.model.steady.TabulatedMotion` (the motion the certificate's
    disturbance is measured from, exactly).
``scales``
    The norm's ``a_i`` (6,), rad and rad/rad.
``function``
    ``family``: ``"quadratic"`` with ``Q`` (6, 6, state units) and ``solution``: ``P`` in scaled
    coordinates as :class:`~rotorlyap.methods.periodic_lyapunov.PeriodicLyapunovSolution` holds it
    (``interpolation`` "constant" or "hermite", ``psi``, ``P_grid`` and ``dP_grid`` (K, 6, 6), its
    diagnostics and the Floquet monodromy matrix); or ``"energy"`` / ``"polynomial"`` with the
    basis described (``harmonics``, ``degrees``, for the energy ``energy_reference`` H_ref in J),
    its ``names`` and ``coefficients``, and the design's numbers (``design``, for the reader, not
    checked: the start radius and bound it was made for, its rounds and constraints, and ``tried``,
    the scenario program's attempts ``[lam, A, designed]`` in order).
``claims``
    ``rule = "sound"``, the bound ``A``, the ``level`` c, ``lambda0`` per azimuth ``2 pi j / n``
    (scaled norm), the ``period``, and for the reader the ``band_max_dW`` the engine found and the
    ``tol`` it had to be below.
``search``
    The engine's settings the final check runs with (``margin``, ``n_sphere``, ...; each at least
    the engine's default: a file cannot ask for a weaker check).
``summary``
    The certificate's own summary, for the reader (not checked).

The checks of :func:`verify`: ``steady motion`` (the table solves the blade's equations: the
largest residual ``|xi' - h(psi, xi)|`` at the tabulated points, in the scaled norm, relative to
the largest rate ``|h|`` there or to 1 per rad, below :data:`STEADY_RESIDUAL_TOL`); ``level``,
``start`` and ``band`` (:func:`rotorlyap.methods.certificate_check.check_claims`: the level facts
and condition (h) by the sound rule's final check); with ``prove=True`` and a quadratic function,
``proof`` (:func:`rotorlyap.analysis.proof.prove_blade` up to the bound). The falsifier of the
tests (``tests/falsifier*.py``) is test code, not part of the package: :func:`verify` does not run
it.
"""

from __future__ import annotations

import inspect
import json
import math
import re
import tempfile
import warnings
from dataclasses import dataclass, fields
from pathlib import Path

import numpy as np

from ..conventions import TWO_PI
from ..errors import CertificateFileError, TemplateValuesWarning
from ..methods.certificate_check import Check, check_claims
from ..methods.floquet import FloquetResult
from ..methods.lyapunov import technical_stability
from ..methods.periodic_lyapunov import PeriodicLyapunovSolution
from ..methods.scenario import BasisFunction, Design
from ..model.blade import Blade
from ..model.forward_trim import TRIM_TARGETS
from ..model.parameters import BladeParameters
from ..model.steady import SteadyMotion, TabulatedMotion, disturbed_rhs
from ..reporting import count, format_small
from .functions import QuadraticFunction
from .nonlinear_functions import (DESIGN_EFFORTS, FAMILIES, DesignedFunction, basis_harmonics, energy_basis,
                                  energy_reference, is_autonomous, polynomial_basis)
from .stability import psi_free_system

__all__ = ["FAMILY_WORDS", "FORMAT", "STEADY_RESIDUAL_TOL", "VERSION", "StoredCertificate", "Verification", "read_certificate",
           "save_certificate", "verify"]

#: A function family in words (the file's ``function.family``): "energy" is the augmented energy,
#: not the blade's energy alone (the book's "energy function").
FAMILY_WORDS = {"quadratic": "quadratic function", "energy": "augmented energy",
                 "polynomial": "polynomial function"}

#: A flight condition in words (:data:`rotorlyap.model.forward_trim.TRIM_TARGETS`).
_CONDITION_WORDS = {"propulsive": "propulsive trim", "flapping": "flapping trim",
                    "none": "the paper's condition (no trim)"}

#: The format name a certificate file declares.
FORMAT = "rotorlyap.certificate"

#: The format version this package writes and reads.
VERSION = 1

#: Largest relative residual of the stored steady motion (module docstring): a Fourier series
#: collocated at 64 azimuths and tabulated (:func:`rotorlyap.model.steady.tabulate_motion`) has
#: about 4e-4 in forward flight at mu = 0.1, a shooting-refined motion or a hover equilibrium
#: round-off.
STEADY_RESIDUAL_TOL = 1e-3

#: Azimuths at which a constant steady motion's residual is checked (uniform on the period).
CONSTANT_AZIMUTHS = 64

#: The engine's settings the final check runs with, and their defaults (those of
#: :func:`rotorlyap.technical_stability`): a file may ask for more, never for less.
SEARCH_SETTINGS = ("margin", "n_sphere", "n_radii", "n_shells", "n_bisect", "n_refine", "n_iter", "fd_step",
                   "seed")
_CONTROLS = ("collective", "cyclic_cos", "cyclic_sin", "shaft_tilt", "inflow_ratio")
_PARAMETER_FILE = "blade.toml"


def _search_defaults() -> dict:
    defaults = inspect.signature(technical_stability).parameters
    return {name: defaults[name].default for name in SEARCH_SETTINGS}


def _package_version() -> str:
    try:
        from importlib.metadata import version

        return version("rotorlyap")
    except Exception:  # noqa: BLE001 (not installed: the source tree on the path)
        return "unknown"


# ------------------------------------------------------------------------------------ writing


def _floats(a) -> list | float:
    """An array as nested lists of Python floats (written by ``repr``: bit-exact)."""
    return np.asarray(a, dtype=float).tolist()


def _blade_files(params: BladeParameters) -> dict:
    """The parameter file of ``params`` and the files it names, as text; refused where the file
    would read back another blade (a C81 table off the printed grid, a callable profile)."""
    with tempfile.TemporaryDirectory() as tmp:
        target = Path(tmp) / _PARAMETER_FILE
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("error", UserWarning)  # a rounded C81 table: refused below
                params.to_file(target)
        except (ValueError, UserWarning) as exc:
            raise ValueError(f"the blade cannot be stored in a certificate file: {exc}") from exc
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", TemplateValuesWarning)
            back = BladeParameters.from_file(target)
        if back != params:
            differ = [f.name for f in fields(params) if getattr(back, f.name) != getattr(params, f.name)]
            raise ValueError(f"the blade cannot be stored in a certificate file: its parameter file reads back "
                             f"other values of {differ}")
        files = {p.name: p.read_text(encoding="utf-8") for p in sorted(Path(tmp).iterdir())
                 if p.name != _PARAMETER_FILE}
        return {"parameters_toml": target.read_text(encoding="utf-8"), "files": files}


def _steady_json(steady: SteadyMotion) -> dict:
    if steady.is_constant:
        return {"kind": "constant", "label": steady.label, "state": _floats(steady.state)}
    table = getattr(steady.xi_function, "__self__", None)
    if not isinstance(table, TabulatedMotion) or getattr(steady.dxi_function, "__self__", None) is not table:
        raise ValueError("a certificate file holds a constant steady motion or a TabulatedMotion "
                         "(rotorlyap.model.steady.tabulate_motion or refine_motion), got " + repr(steady))
    return {"kind": "hermite", "label": table.label, "max_error": float(table.max_error),
            "values": _floats(table.values), "slopes": _floats(table.slopes)}


def _quadratic_json(fun: QuadraticFunction) -> dict:
    sol = fun.solution
    if sol.interpolation not in ("constant", "hermite"):
        raise ValueError(f"a certificate file holds a constant or Hermite P(psi), got {sol.interpolation!r}")
    fl = sol.floquet
    return {
        "family": "quadratic", "label": fun.label, "Q": _floats(fun.Q),
        "solution": {
            "period": float(sol.period), "Q": _floats(sol.Q), "interpolation": sol.interpolation,
            "psi": _floats(sol.psi), "P_grid": _floats(sol.P_grid), "dP_grid": _floats(sol.dP_grid),
            "method": sol.method, "n_grid": int(sol.n_grid),
            **{k: float(getattr(sol, k)) for k in ("residual", "relative_residual", "residual_eigenvalue",
                                                    "periodicity_error", "min_eigenvalue", "max_eigenvalue")},
            "floquet": {"monodromy": _floats(fl.monodromy), "tol": float(fl.tol), "method": fl.method,
                        "trace_integral": float(fl.trace_integral),
                        "n_steps": None if fl.n_steps is None else int(fl.n_steps),
                        "error_estimate": float(fl.error_estimate) if math.isfinite(fl.error_estimate) else None,
                        "n_evaluations": int(fl.n_evaluations),
                        "multipliers": _floats(np.column_stack([fl.multipliers.real, fl.multipliers.imag]))},
        },
    }


def _degree(name: str) -> int:
    """Total degree of a monomial basis name (``"flap^2*lag*cos(1psi)"`` -> 3)."""
    return sum(int(p.partition("^")[2] or 1) for p in name.split("*") if "(" not in p)


def _designed_json(fun: DesignedFunction) -> dict:
    bf, d = fun.function, fun.design
    names = list(bf.basis.names)
    monomials = [n for n in names if n != "energy"]
    data = {"family": fun.family, "label": fun.label, "harmonics": fun.harmonics,
            "degrees": sorted({_degree(n) for n in monomials}), "names": names,
            "coefficients": _floats(bf.coefficients),
            "design": {"lam": float(d.lam), "A": float(d.A), "margin": float(d.margin), "feasible": bool(d.feasible),
                       "rounds": int(d.rounds), "n_constraints": int(d.n_constraints), "effort": fun.effort,
                       "tried": [[float(lam), float(A), bool(ok)] for lam, A, ok in d.tried]}}
    if fun.family == "energy":
        data["energy_reference"] = energy_reference(fun.blade, fun.steady, scales=fun.scales)
    return data


def save_certificate(cert, path: str | Path) -> Path:
    """Write a certificate as a JSON file that :func:`verify` checks.

    Parameters
    ----------
    cert : rotorlyap.analysis.certify.Certificate
        A certificate of the sound rule (``cert.certified``).
    path : str or pathlib.Path
        The file to write (overwritten); ``.json`` by convention.

    Returns
    -------
    pathlib.Path
        The file written.

    Raises
    ------
    ValueError
        Nothing certified (nothing to check), another rule than the sound rule, a function or a
        steady motion the format does not hold, or a blade whose parameter file would read back
        another blade (a C81 table off the printed grid of a C81 file, a callable profile).
    """
    res = getattr(cert, "result", None)
    if not getattr(cert, "certified", False) or res is None:
        raise ValueError(f"nothing is certified, so there is nothing to save: {getattr(cert, 'message', cert)!r}")
    if res.rule != "sound" or res.reading != "strict":
        raise ValueError(f"a certificate file holds a certificate of the sound rule (strict reading), got rule="
                         f"{res.rule!r}, reading={res.reading!r}")
    fun = cert.lyapunov
    if isinstance(fun, QuadraticFunction):
        function = _quadratic_json(fun)
    elif isinstance(fun, DesignedFunction):
        function = _designed_json(fun)
    else:
        raise ValueError(f"a certificate file holds a quadratic or a designed function, got {type(fun).__name__}")
    if not np.array_equal(np.asarray(fun.scales, dtype=float), np.asarray(cert.scales, dtype=float)):
        raise ValueError("the function's scales differ from the certificate's")
    params = cert.trim.params
    data = {
        "format": FORMAT, "version": VERSION, "package_version": _package_version(),
        "blade": _blade_files(params),
        "flight": {"mu": float(cert.mu), "condition": cert.condition,
                   "controls": {k: None if getattr(params, k) is None else float(getattr(params, k))
                                for k in _CONTROLS}},
        "steady_motion": _steady_json(fun.steady),
        "scales": _floats(cert.scales),
        "function": function,
        "claims": {"rule": "sound", "A": float(res.A), "level": float(res.level), "period": float(res.period),
                   "lambda0": _floats(res.lambda0), "band_max_dW": float(res.band_max_dW), "tol": float(res.tol)},
        "search": _search_defaults(),
        "summary": cert.summary(),
    }
    path = Path(path)
    path.write_text(_dumps(data), encoding="utf-8")
    return path


def _dumps(data: dict) -> str:
    """``data`` as JSON text: objects indented, each array of numbers on one line (not one line
    per number: a table of 4096 states would be some 30,000 lines); floats by ``repr``."""
    arrays = []

    def numeric(obj) -> bool:
        return isinstance(obj, list) and bool(obj) and all(
            numeric(v) if isinstance(v, list) else isinstance(v, (int, float)) and not isinstance(v, bool) for v in obj)

    def mark(obj):
        if isinstance(obj, dict):
            return {k: mark(v) for k, v in obj.items()}
        if numeric(obj):
            arrays.append(json.dumps(obj, separators=(",", ":"), allow_nan=False))
            return f"\x00{len(arrays) - 1}\x00"
        return obj

    text = json.dumps(mark(data), indent=1, allow_nan=False)
    return re.sub(r'"\\u0000(\d+)\\u0000"', lambda m: arrays[int(m.group(1))], text) + "\n"


# ------------------------------------------------------------------------------------ reading


class _Fields:
    """Typed access to the parsed JSON, each failure a :class:`CertificateFileError` naming the
    file and the field and saying what is allowed."""

    def __init__(self, path: Path):
        self.path = path

    def fail(self, where: str, message: str) -> CertificateFileError:
        return CertificateFileError(f"{self.path}: {where}: {message}")

    def get(self, obj: dict, key: str, where: str):
        if not isinstance(obj, dict):
            raise self.fail(where, f"must be a JSON object, got {type(obj).__name__}")
        if key not in obj:
            raise self.fail(f"{where}.{key}" if where else key, "missing (a required field of format "
                                                                 f"{FORMAT} version {VERSION})")
        return obj[key]

    def number(self, obj: dict, key: str, where: str, *, positive: bool = False, optional: bool = False):
        v = self.get(obj, key, where)
        name = f"{where}.{key}" if where else key
        if v is None and optional:
            return None
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
            raise self.fail(name, f"must be a finite number, got {v!r}")
        if positive and not v > 0:
            raise self.fail(name, f"must be > 0, got {v!r}")
        return float(v)

    def integer(self, obj: dict, key: str, where: str, minimum: int = 0) -> int:
        v = self.get(obj, key, where)
        if isinstance(v, bool) or not isinstance(v, int) or v < minimum:
            raise self.fail(f"{where}.{key}", f"must be an integer >= {minimum}, got {v!r}")
        return v

    def text(self, obj: dict, key: str, where: str, choices=None) -> str:
        v = self.get(obj, key, where)
        if not isinstance(v, str) or (choices is not None and v not in choices):
            allowed = f"one of {tuple(choices)}" if choices is not None else "a string"
            raise self.fail(f"{where}.{key}" if where else key, f"must be {allowed}, got {v!r}")
        return v

    def array(self, obj: dict, key: str, where: str, shape: tuple) -> np.ndarray:
        """A float array of ``shape`` (None: any length on that axis) from nested lists of numbers."""
        v = self.get(obj, key, where)
        name = f"{where}.{key}" if where else key

        def check(item, depth):
            if depth == len(shape):
                if isinstance(item, bool) or not isinstance(item, (int, float)) or not math.isfinite(item):
                    raise self.fail(name, f"must hold finite numbers only, found {item!r}")
                return
            if not isinstance(item, list) or (shape[depth] is not None and len(item) != shape[depth]):
                raise self.fail(name, f"must be an array of shape {_shape_text(shape)}")
            for sub in item:
                check(sub, depth + 1)

        check(v, 0)
        out = np.array(v, dtype=float)
        if out.ndim != len(shape) or 0 in out.shape:
            raise self.fail(name, f"must be a non-empty array of shape {_shape_text(shape)}, got shape {out.shape}")
        return out


def _shape_text(shape: tuple) -> str:
    return "(" + ", ".join("n" if s is None else str(s) for s in shape) + ")"


@dataclass(frozen=True)
class StoredCertificate:
    """A certificate file read back (:func:`read_certificate`): the numbers and the rebuilt objects.

    Attributes
    ----------
    path : pathlib.Path
    params : BladeParameters
        The blade with its trimmed controls.
    mu : float
        Advance ratio.
    condition : str
        The flight condition (:data:`rotorlyap.model.forward_trim.TRIM_TARGETS`).
    blade : Blade
    steady : SteadyMotion
        The steady motion the disturbance is measured from (the stored table).
    function : QuadraticFunction or DesignedFunction
        Rebuilt from the stored coefficients (``W``, ``dW``, ``f``).
    scales : numpy.ndarray
        The norm's ``a_i``, rad and rad/rad.
    A, level : float
        The claimed bound (scaled norm) and level (unit of ``W``).
    lambda0 : numpy.ndarray
        The claimed start radius per azimuth ``period j / n`` (scaled norm).
    period : float
        rad.
    band_max_dW, tol : float
        The largest ``W'`` on the band the engine found, and what it had to be below.
    search : dict
        The engine's settings of the final check (:data:`SEARCH_SETTINGS`).
    data : dict
        The parsed JSON.
    """

    path: Path
    params: BladeParameters
    mu: float
    condition: str
    blade: Blade
    steady: SteadyMotion
    function: object
    scales: np.ndarray
    A: float
    level: float
    lambda0: np.ndarray
    period: float
    band_max_dW: float
    tol: float
    search: dict
    data: dict

    @property
    def family(self) -> str:
        """``"quadratic"``, ``"energy"`` or ``"polynomial"``."""
        return "quadratic" if isinstance(self.function, QuadraticFunction) else self.function.family


def _load_json(path: Path) -> dict:
    try:
        text = path.read_text(encoding="utf-8")
    except UnicodeDecodeError as exc:
        raise CertificateFileError(f"{path}: not a text file (UTF-8 JSON): {exc}") from exc

    def refuse(name):
        raise CertificateFileError(f"{path}: holds {name}: a certificate file holds finite numbers only")

    try:
        data = json.loads(text, parse_constant=refuse)
    except json.JSONDecodeError as exc:
        raise CertificateFileError(f"{path}: not a complete JSON document (truncated or not JSON): {exc}") from exc
    if not isinstance(data, dict):
        raise CertificateFileError(f"{path}: a certificate file is a JSON object, got a {type(data).__name__}")
    fmt, version = data.get("format"), data.get("version")
    if fmt != FORMAT:
        raise CertificateFileError(f'{path}: not a rotorlyap certificate file: format must be "{FORMAT}", got {fmt!r}')
    if version != VERSION or isinstance(version, bool):
        raise CertificateFileError(f"{path}: format version {version!r} is not known to this rotorlyap, which reads "
                                   f"version {VERSION}")
    return data


def _read_blade(r: _Fields, data: dict) -> BladeParameters:
    blade = r.get(data, "blade", "")
    toml = r.text(blade, "parameters_toml", "blade")
    files = r.get(blade, "files", "blade")
    if not isinstance(files, dict) or not all(isinstance(k, str) and isinstance(v, str) for k, v in files.items()):
        raise r.fail("blade.files", "must be an object of file name -> text")
    with tempfile.TemporaryDirectory() as tmp:
        for name, text in files.items():
            if Path(name).name != name or name in ("", ".", "..", _PARAMETER_FILE):
                raise r.fail("blade.files", f"a file name without a directory, other than {_PARAMETER_FILE}, "
                                            f"got {name!r}")
            (Path(tmp) / name).write_text(text, encoding="utf-8")
        target = Path(tmp) / _PARAMETER_FILE
        target.write_text(toml, encoding="utf-8")
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", TemplateValuesWarning)
                return BladeParameters.from_file(target)
        except (ValueError, TypeError, OSError) as exc:
            raise r.fail("blade.parameters_toml", f"not a valid blade parameter file: {exc}") from exc


def _read_steady(r: _Fields, data: dict) -> SteadyMotion:
    st = r.get(data, "steady_motion", "")
    kind = r.text(st, "kind", "steady_motion", ("constant", "hermite"))
    label = r.text(st, "label", "steady_motion")
    if kind == "constant":
        return SteadyMotion.constant(r.array(st, "state", "steady_motion", (6,)), label)
    values = r.array(st, "values", "steady_motion", (None, 6))
    slopes = r.array(st, "slopes", "steady_motion", (values.shape[0], 6))
    if values.shape[0] < 8:
        raise r.fail("steady_motion.values", f"a table of at least 8 azimuths, got {values.shape[0]}")
    table = TabulatedMotion(values=values, slopes=slopes,
                            max_error=r.number(st, "max_error", "steady_motion"), label=label)
    return table.steady  # as rotorlyap.certify took it (a table that does not move is constant)


def _read_quadratic(r: _Fields, fun: dict, blade: Blade, steady: SteadyMotion, a: np.ndarray) -> QuadraticFunction:
    w = "function.solution"
    sol = r.get(fun, "solution", "function")
    interpolation = r.text(sol, "interpolation", w, ("constant", "hermite"))
    psi = r.array(sol, "psi", w, (None,))
    k = psi.size
    if interpolation == "constant" and k != 1:
        raise r.fail(f"{w}.psi", f"a constant P has one grid point, got {k}")
    if r.integer(sol, "n_grid", w, 1) != k:
        raise r.fail(f"{w}.n_grid", f"must equal the number of grid points in psi, {k}")
    fl = r.get(sol, "floquet", w)
    mult = r.array(fl, "multipliers", f"{w}.floquet", (6, 2))
    mu = mult[:, 0] + 1j * mult[:, 1]
    period = _blade_period(r, sol, w)
    tol = r.number(fl, "tol", f"{w}.floquet")
    rho = float(np.max(np.abs(mu)))
    with np.errstate(divide="ignore"):
        floquet = FloquetResult(
            monodromy=r.array(fl, "monodromy", f"{w}.floquet", (6, 6)), multipliers=mu, exponents=np.log(mu) / period,
            spectral_radius=rho, stable=bool(rho < 1.0 - tol), period=period, tol=tol,
            trace_integral=r.number(fl, "trace_integral", f"{w}.floquet"), method=r.text(fl, "method", f"{w}.floquet"),
            n_steps=None if fl.get("n_steps") is None else r.integer(fl, "n_steps", f"{w}.floquet", 1),
            error_estimate=_or_nan(r.number(fl, "error_estimate", f"{w}.floquet", optional=True)),
            n_evaluations=r.integer(fl, "n_evaluations", f"{w}.floquet"))
    solution = PeriodicLyapunovSolution(
        period=period, Q=r.array(sol, "Q", w, (6, 6)), psi=psi, P_grid=r.array(sol, "P_grid", w, (k, 6, 6)),
        dP_grid=r.array(sol, "dP_grid", w, (k, 6, 6)), interpolation=interpolation, coefficients=None,
        floquet=floquet, method=r.text(sol, "method", w), n_grid=r.integer(sol, "n_grid", w, 1),
        **{key: r.number(sol, key, w) for key in ("residual", "relative_residual", "residual_eigenvalue",
                                                  "periodicity_error", "min_eigenvalue", "max_eigenvalue")})
    return QuadraticFunction(blade=blade, steady=steady, Q=r.array(fun, "Q", "function", (6, 6)), scales=a,
                             solution=solution, label=r.text(fun, "label", "function"))


def _blade_period(r: _Fields, obj: dict, where: str) -> float:
    """The stored period, which must be the blade's, 2 pi rad (a shorter one would search part of it)."""
    period = r.number(obj, "period", where)
    if period != TWO_PI:
        raise r.fail(f"{where}.period", f"must be the blade's period 2 pi = {TWO_PI!r} rad, got {period!r}")
    return period


def _or_nan(value: float | None) -> float:
    return math.nan if value is None else value


def _read_designed(r: _Fields, fun: dict, family: str, blade: Blade, steady: SteadyMotion,
                   a: np.ndarray) -> DesignedFunction:
    w = "function"
    try:  # the bases' own rule: >= 0, and 0 where the blade is autonomous
        harmonics = basis_harmonics(blade, steady, r.integer(fun, "harmonics", w))
    except ValueError as exc:
        raise r.fail("function.harmonics", str(exc)) from None
    degrees = r.get(fun, "degrees", w)
    if not isinstance(degrees, list) or not degrees or not all(isinstance(d, int) and not isinstance(d, bool)
                                                               and d >= 2 for d in degrees):
        raise r.fail("function.degrees", f"must be a non-empty list of integers >= 2, got {degrees!r}")
    if family == "energy":
        if degrees != [2]:
            raise r.fail("function.degrees", f"the augmented energy's monomials are quadratic: [2], got {degrees!r}")
        basis = energy_basis(blade, steady, scales=a, harmonics=harmonics,
                             reference=r.number(fun, "energy_reference", w, positive=True))
    else:
        basis = polynomial_basis(blade, steady, scales=a, degrees=tuple(degrees), harmonics=harmonics)
    names = r.get(fun, "names", w)
    if names != list(basis.names):
        raise r.fail("function.names", f"the basis described (family {family!r}, harmonics {harmonics}, degrees "
                                       f"{degrees}) has {basis.size} functions {list(basis.names)[:3]} ..., which "
                                       "the names listed must equal")
    coefficients = r.array(fun, "coefficients", w, (basis.size,))
    d = r.get(fun, "design", w)
    bf = BasisFunction(basis, coefficients, disturbed_rhs(blade, steady), r.text(fun, "label", w))
    design = Design(function=bf, lam=r.number(d, "lam", "function.design"), A=r.number(d, "A", "function.design"),
                    margin=r.number(d, "margin", "function.design"),
                    feasible=bool(r.get(d, "feasible", "function.design")),
                    rounds=r.integer(d, "rounds", "function.design"),
                    n_constraints=r.integer(d, "n_constraints", "function.design"))
    effort = d.get("effort", "default")  # a file written before efforts were recorded: the default's
    if effort not in DESIGN_EFFORTS:
        raise r.fail("function.design.effort", f"must be one of {tuple(DESIGN_EFFORTS)}, got {effort!r}")
    return DesignedFunction(blade=blade, steady=steady, family=family, design=design, scales=a,
                            autonomous=is_autonomous(blade, steady), label=bf.label, effort=effort)


def read_certificate(path: str | Path) -> StoredCertificate:
    """Read a certificate file and rebuild what it stores; nothing is checked
    beyond the file's form (:func:`verify` checks the claims).

    Parameters
    ----------
    path : str or pathlib.Path

    Returns
    -------
    StoredCertificate

    Raises
    ------
    rotorlyap.errors.CertificateFileError
        A file that is not JSON or truncated, of another format or version, with a field missing,
        of the wrong type or shape, a non-finite number, a blade that does not read, controls that
        differ from the blade's, a basis that does not match its description, or search settings
        weaker than the engine's defaults. A ``ValueError``.
    OSError
        No such file.
    """
    path = Path(path)
    data = _load_json(path)
    r = _Fields(path)
    params = _read_blade(r, data)
    flight = r.get(data, "flight", "")
    mu = r.number(flight, "mu", "flight")
    condition = r.text(flight, "condition", "flight", TRIM_TARGETS)
    controls = r.get(flight, "controls", "flight")
    for key in _CONTROLS:
        stored = r.number(controls, key, "flight.controls", optional=True)
        if stored != getattr(params, key):
            raise r.fail(f"flight.controls.{key}", f"{stored!r} differs from the blade's {getattr(params, key)!r} "
                                                   "(blade.parameters_toml): the two must be equal")
    try:
        blade = Blade(params, mu)
    except (ValueError, TypeError, RuntimeError) as exc:
        raise r.fail("flight.mu", str(exc)) from exc
    steady = _read_steady(r, data)
    a = r.array(data, "scales", "", (6,))
    if np.any(a <= 0):
        raise r.fail("scales", f"must be 6 numbers > 0 (rad, rad/rad), got {a.tolist()}")
    fun_data = r.get(data, "function", "")
    family = r.text(fun_data, "family", "function", ("quadratic",) + FAMILIES)
    try:
        function = (_read_quadratic(r, fun_data, blade, steady, a) if family == "quadratic"
                    else _read_designed(r, fun_data, family, blade, steady, a))
    except CertificateFileError:
        raise
    except ValueError as exc:
        raise r.fail("function", str(exc)) from exc
    claims = r.get(data, "claims", "")
    r.text(claims, "rule", "claims", ("sound",))
    A = r.number(claims, "A", "claims", positive=True)
    lam = r.array(claims, "lambda0", "claims", (None,))
    if np.any(lam <= 0) or np.any(lam > A):
        raise r.fail("claims.lambda0", f"every start radius must lie in (0, A = {A!r}], got values in "
                                       f"[{lam.min()!r}, {lam.max()!r}]")
    search_data = r.get(data, "search", "")
    search = {}
    for key, default in _search_defaults().items():
        value = r.integer(search_data, key, "search") if isinstance(default, int) else \
            r.number(search_data, key, "search", positive=key != "margin")
        weaker = (key in ("margin",) and value < default) or (isinstance(default, int) and key != "seed"
                                                              and value < default)
        if weaker:
            raise r.fail(f"search.{key}", f"{value!r} asks for a weaker check than the engine's default "
                                          f"{default!r}: at least the default is allowed")
        search[key] = value
    return StoredCertificate(
        path=path, params=params, mu=mu, condition=condition, blade=blade, steady=steady, function=function,
        scales=a, A=A, level=r.number(claims, "level", "claims", positive=True), lambda0=lam,
        period=_blade_period(r, claims, "claims"),
        band_max_dW=r.number(claims, "band_max_dW", "claims"), tol=r.number(claims, "tol", "claims"),
        search=search, data=data)


# ------------------------------------------------------------------------------------ checking


@dataclass(frozen=True)
class Verification:
    """Result of :func:`verify`: every check of a certificate file, and the verdict.

    Attributes
    ----------
    path : str
        The file checked.
    holds : bool
        Every check holds: the file is a numerical certificate (with ``prove=True``, also proved):
        every motion that starts, at any azimuth, with ``||x|| < A`` and ``W < c`` (the start set
        of :func:`rotorlyap.methods.start_set.start_set`, which holds the balls ``lambda0``) stays
        within ``||x|| < A``.
    checks : tuple of Check
        ``steady motion``, ``level``, ``start``, ``band`` (and ``proof``), each with ``holds``,
        ``value``, ``limit``, ``margin``, ``meaning`` and ``detail``
        (:class:`rotorlyap.methods.certificate_check.Check`).
    mu : float
        Advance ratio.
    condition : str
    function : str
        ``"quadratic"``, ``"energy"`` or ``"polynomial"``.
    bound : float
        The claimed bound ``A``, scaled norm.
    level : float
        The claimed level ``c``.
    start_region : float
        The smallest claimed start radius, scaled norm.
    harmonics : int
        A designed function's harmonics of the azimuth in its coefficients (0: constant ones, and
        for the quadratic function, whose ``P(psi)`` is tabulated).
    """

    path: str
    holds: bool
    checks: tuple
    mu: float
    condition: str
    function: str
    bound: float
    level: float
    start_region: float
    harmonics: int = 0

    def __getitem__(self, name: str) -> Check:
        for check in self.checks:
            if check.name == name:
                return check
        raise KeyError(f"no check {name!r}; the checks are {[c.name for c in self.checks]}")

    def summary(self) -> str:
        """The verdict and one line per check, rounded to the digits the checks determine (values
        to 3 significant digits, margins to 2; round-off-level numbers as bounds,
        :func:`rotorlyap.reporting.format_small`); a failing check adds its numbers."""
        head = (f"{'VERIFIED' if self.holds else 'REFUSED'}: mu = {self.mu:g}, {_CONDITION_WORDS[self.condition]}, "
                f"{FAMILY_WORDS[self.function]}"
                + (f" ({count(self.harmonics, 'harmonic')} of the azimuth)" if self.harmonics else "")
                + f", bound A = {self.bound:.3g}, start region {self.start_region:.3g} "
                "(scaled norm)")
        lines = [head]
        width = max(len(c.name) for c in self.checks)
        for c in self.checks:
            margin = format_small(c.margin, 1e-6) if 0 <= c.margin < 1e-6 else f"{c.margin:.2g}"
            lines.append(f"  {'holds' if c.holds else 'FAILS'}  {c.name:<{width}}  {c.quantity}: {_rounded(c.value)} / "
                         f"{_rounded(c.limit)} (margin {margin})")
            if not c.holds:
                lines.append(f"         {c.detail}")
        return "\n".join(lines)

    def __str__(self) -> str:
        return self.summary()


def _rounded(value: float) -> str:
    """3 significant digits; a round-off-level magnitude as a bound."""
    return format_small(value, 1e-10) if 0 <= value < 1e-10 else f"{value:.3g}"


def _steady_check(stored: StoredCertificate) -> Check:
    """The steady-motion table against the blade's equations."""
    a, blade, steady = stored.scales, stored.blade, stored.steady
    if steady.is_constant:
        psi = stored.period * np.arange(CONSTANT_AZIMUTHS) / CONSTANT_AZIMUTHS
        xi, dxi = steady.xi(psi), steady.dxi(psi)
    else:
        table = steady.xi_function.__self__
        n = table.values.shape[0]
        psi = 2 * np.pi * np.arange(n) / n
        xi, dxi = table.values, table.slopes
    h = blade.rhs(psi, xi)
    residual = np.linalg.norm((dxi - h) / a, axis=1)
    rates = float(np.linalg.norm(h / a, axis=1).max())
    j = int(np.argmax(residual))
    rel = float(residual[j] / max(rates, 1.0))
    holds = bool(rel < STEADY_RESIDUAL_TOL)
    return Check("steady motion", holds, rel, STEADY_RESIDUAL_TOL,
                 float(1.0 - rel / STEADY_RESIDUAL_TOL),
                 "the stored steady motion solves the blade's equations (the disturbance is measured from it)",
                 f"largest residual |xi' - h(psi, xi)| at the {psi.size} tabulated azimuths is "
                 f"{format_small(float(residual[j]), 1e-10)} per rad (scaled norm) at psi = "
                 f"{np.degrees(psi[j]):.4g} deg, "
                 f"relative {format_small(rel, 1e-10)} (to the largest rate {rates:.3g} or 1); it must be below "
                 f"{STEADY_RESIDUAL_TOL:g}" + ("" if holds else ": the table does NOT solve the equations"),
                 "relative residual / the tolerance")


def _proof_check(stored: StoredCertificate) -> Check:
    from .proof import prove_blade

    proof = prove_blade(stored.function, stored.A)
    holds = bool(proof.proved)
    return Check("proof", holds, float(proof.A), stored.A, float(proof.A / stored.A) if holds else -np.inf,
                 "the same function proves, by ball arithmetic, a certificate for the model in exact arithmetic up to "
                 "the bound shown, usually below the numerical one (rotorlyap.analysis.proof.prove_blade)",
                 f"proved bound {proof.A:.3g}, start radius {proof.min_lambda0:.3g} (scaled norm), the numerical "
                 f"bound {stored.A:.3g}: {proof.message}", "proved bound / the numerical bound")


def verify(path: str | Path, *, prove: bool = False) -> Verification:
    """Check a certificate file from nothing but the file.

    Parameters
    ----------
    path : str or pathlib.Path
        A file written by :func:`save_certificate` (:meth:`rotorlyap.Certificate.save`).
    prove : bool
        Also prove a quadratic function's certificate by ball arithmetic
        (:func:`rotorlyap.analysis.proof.prove_blade`: seconds in hover, minutes in forward flight).

    Returns
    -------
    Verification
        ``holds`` and every check; a claim that fails is a check that fails, with the numbers.

    Raises
    ------
    rotorlyap.errors.CertificateFileError
        A file that cannot be read as a certificate (:func:`read_certificate`).
    ValueError
        ``prove=True`` for a designed function (the prover encloses quadratic functions).
    """
    stored = read_certificate(path)
    fun = stored.function
    if prove and not isinstance(fun, QuadraticFunction):
        raise ValueError(f"prove=True proves a quadratic function; this certificate's is {stored.family!r}")
    a = stored.scales
    options = dict(stored.search)
    if isinstance(fun, QuadraticFunction):  # as rotorlyap.analysis.stability.blade_stability gives it
        options["w_matrix"] = lambda psi: a[:, None] * fun.P(psi) * a[None, :]
    else:
        options.update(fun.engine_options())
    options["psi_free"] = psi_free_system(stored.blade, stored.steady, fun.f, fun, a)
    checks = [_steady_check(stored)]
    checks += check_claims(fun.f, fun.W, fun.dW, level=stored.level, A=stored.A, lambda0=stored.lambda0, scales=a,
                           period=stored.period, **options)
    if prove:
        checks.append(_proof_check(stored))
    return Verification(path=str(stored.path), holds=all(c.holds for c in checks), checks=tuple(checks),
                        mu=stored.mu, condition=stored.condition, function=stored.family, bound=stored.A,
                        level=stored.level, start_region=float(np.min(stored.lambda0)),
                        harmonics=0 if isinstance(fun, QuadraticFunction) else fun.harmonics)
