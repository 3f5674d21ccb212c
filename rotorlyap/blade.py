"""The isolated rigid three-hinge blade: equations of motion, aerodynamics, energy function.

:class:`Blade` evaluates the model derived in :mod:`rotorlyap.derivation` (loaded from the
cached generated code, never re-derived at import) together with quasi-steady strip-theory
aerodynamics, hinge dampers and the induced inflow of :mod:`rotorlyap.inflow`.

State and units
---------------
``z = (beta, zeta, theta, beta', zeta', theta')``: flap, lag and pitch hinge angles (rad) and
their derivatives with respect to the azimuth ``psi = Omega t`` (rad/rad).  Every method takes
``z`` of shape ``(..., 6)`` and ``psi`` a float or an array broadcasting with ``z.shape[:-1]``.

Equations of motion
-------------------
``Omega^2 M(q) q'' = F(q, q') + Q_damp + Q_aero`` where ``M`` (kg m^2) and the conservative
forces ``F`` (N m: centrifugal, Coriolis, gravity, hinge springs with the pitch control and the
pitch-flap coupling) come from the generated code, ``Q_damp = -C Omega q'`` (the hinge
dampers, opposing the hinge rates), and ``Q_aero`` is the virtual work of the strip loads.

Aerodynamics
------------
Quasi-steady 2-D strips at ``params.n_stations`` Gauss-Legendre stations on ``[R - R1, R]``.
At each station the air velocity relative to the aerodynamic centre, in blade components, is
``w = C_BH a_H - v`` with the air velocity relative to the hub ``a_N = (mu Omega R, 0,
-lambda_i Omega R)`` (``a_H = (mu Omega R cos psi, -mu Omega R sin psi, -lambda_i Omega R)``)
and ``v = v_P + omega x rho`` the inertial velocity of the aerodynamic centre.  Only the
in-plane components ``(w_y, w_z)`` are used (no radial flow effects).  The angle of attack is
``alpha = atan2(w_z, -w_y) + phi(r)`` over the full circle, with ``phi`` the pretwist; lift
``dL = q c cl`` acts along ``(d_z, -d_y)``, drag ``dD = q c cd`` along the unit in-plane wind
``d = (w_y, w_z)/|w|`` and the moment ``q c^2 cm`` about ``x_B`` at the aerodynamic centre
(``q = rho |w|^2 / 2``).  The pretwist ``phi(r) = twist (r - (R - R1)) / R1`` is zero at the
blade root, so the collective is the pitch of the root section.

Energy (Liapunov) function
--------------------------
See :class:`EnergyFunction`.
"""

from __future__ import annotations

import copy
import math
from dataclasses import dataclass, field, replace
from typing import Callable

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ._generated import blade_model as _gen
from .parameters import BladeParameters

__all__ = ["Blade", "MassProperties", "EnergyFunction", "PositivityReport"]

FloatArray = NDArray[np.float64]

#: States per block in the vectorised kernels: keeps the temporaries in cache (1e5 states are
#: processed in blocks; the result does not depend on it).
CHUNK = 4096

#: Central-difference step of :meth:`Blade.jacobian`, rad and rad/rad.
JACOBIAN_STEP = 1e-6



# --------------------------------------------------------------------------------------
# Mass properties
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class MassProperties:
    """Mass properties of the blade body about the pitch hinge, ``B`` components.

    Attributes
    ----------
    mass : float
        Blade mass, kg.
    first_moment : numpy.ndarray
        ``S = m r_G`` from the pitch hinge, shape (3,), kg m.
    inertia : numpy.ndarray
        Inertia tensor about the pitch hinge ``I_ij = int (rho^2 delta_ij - rho_i rho_j) dm``,
        shape (3, 3), kg m^2 (off-diagonal entries are minus the products of inertia).
    """

    mass: float
    first_moment: FloatArray
    inertia: FloatArray

    @property
    def centre_of_gravity(self) -> FloatArray:
        """Centre of gravity from the pitch hinge, ``B`` components, m."""
        return self.first_moment / self.mass

    @property
    def flap_inertia(self) -> float:
        """Moment of inertia about ``y_B`` through the pitch hinge, kg m^2."""
        return float(self.inertia[1, 1])


def _twist(params: BladeParameters, r: FloatArray) -> FloatArray:
    """Pretwist ``phi(r) = twist (r - (R - R1)) / R1`` (zero at the root), rad."""
    return params.twist * (r - params.root_cutout) / params.blade_length


def mass_properties(params: BladeParameters, n_points: int = 64) -> MassProperties:
    """Mass properties of the blade from its spanwise distribution (Gauss-Legendre quadrature).

    Each section of mass ``m'(r) dr`` has its C.G. at ``cg_position`` (fraction of chord behind
    the leading edge), i.e. at ``(r - r_P, e5 R1 + (x_pa - x_cg) c cos phi, (x_pa - x_cg) c sin
    phi)`` from the pitch hinge (``x_pa`` the pitch axis, ``phi`` the pretwist), and its mass
    spread along the chord line with radius of gyration ``k c`` about the section C.G. (a thin
    section: ``m' k^2 c^2`` about ``x_B`` and about the section normal, nothing about the chord
    line).

    Parameters
    ----------
    params : BladeParameters
    n_points : int
        Quadrature points on ``[R - R1, R]`` (exact for polynomial profiles of degree < 128).

    Returns
    -------
    MassProperties
    """
    x, w = np.polynomial.legendre.leggauss(n_points)
    a, b = params.root_cutout, params.radius
    r = 0.5 * (b - a) * x + 0.5 * (b + a)
    dr = 0.5 * (b - a) * w
    ro = r / params.radius
    dm = params.mass_per_length_at(ro) * dr
    c = params.chord_at(ro)
    phi = _twist(params, r)
    off = (params.pitch_axis - params.cg_position_at(ro)) * c
    rho = np.stack([r - params.pitch_hinge_radius,
                    params.hub_element_lengths[4] + off * np.cos(phi),
                    off * np.sin(phi)], axis=-1)
    e = np.stack([np.zeros_like(phi), np.cos(phi), np.sin(phi)], axis=-1)
    k2 = (params.pitch_radius_of_gyration * c) ** 2
    eye = np.eye(3)
    I = np.einsum("i,ijk->jk", dm, np.einsum("i,jk->ijk", np.einsum("ij,ij->i", rho, rho), eye)
                  - np.einsum("ij,ik->ijk", rho, rho))
    I += np.einsum("i,ijk->jk", dm * k2, eye[None] - np.einsum("ij,ik->ijk", e, e))
    return MassProperties(mass=float(dm.sum()), first_moment=dm @ rho, inertia=I)


# --------------------------------------------------------------------------------------
# Small linear algebra
# --------------------------------------------------------------------------------------


def _solve_sym3(m: FloatArray, b0, b1, b2):
    """Solve the symmetric 3x3 systems ``M x = b`` by the adjugate (closed form).

    ``m`` holds the unique entries 00, 01, 02, 11, 12, 22 along its first axis.
    """
    a, bq, c, d, e, f = m
    A00 = d * f - e * e
    A01 = c * e - bq * f
    A02 = bq * e - c * d
    A11 = a * f - c * c
    A12 = bq * c - a * e
    A22 = a * d - bq * bq
    inv_det = 1.0 / (a * A00 + bq * A01 + c * A02)
    return ((A00 * b0 + A01 * b1 + A02 * b2) * inv_det,
            (A01 * b0 + A11 * b1 + A12 * b2) * inv_det,
            (A02 * b0 + A12 * b1 + A22 * b2) * inv_det)


def _sym3_matvec(m: FloatArray, v0, v1, v2):
    """``M v`` for the symmetric matrices stored as unique entries (see :func:`_solve_sym3`)."""
    a, b, c, d, e, f = m
    return a * v0 + b * v1 + c * v2, b * v0 + d * v1 + e * v2, c * v0 + e * v1 + f * v2


def _flatten(psi: ArrayLike, z: ArrayLike, width: int = 6):
    """Broadcast ``psi`` against ``z[..., :]``; return flat psi (n,), z (n, width) and shape."""
    z = np.asarray(z, dtype=np.float64)
    if z.ndim == 0 or z.shape[-1] != width:
        raise ValueError(f"state must have shape (..., {width}), got {z.shape}")
    psi = np.asarray(psi, dtype=np.float64)
    shape = np.broadcast_shapes(z.shape[:-1], psi.shape)
    zf = np.broadcast_to(z, shape + (width,)).reshape(-1, width)
    pf = np.broadcast_to(psi, shape).reshape(-1)
    return pf, zf, shape


# --------------------------------------------------------------------------------------
# The blade
# --------------------------------------------------------------------------------------


class Blade:
    """The paper's rigid blade with three hinges, in hover or forward flight.

    Parameters
    ----------
    params : BladeParameters
        Blade, rotor and flight parameters.  If ``params.collective`` is None the collective is
        trimmed for thrust = weight in hover (:func:`rotorlyap.trim.hover_trim`).
    mu : float
        Advance ratio ``V / (Omega R)``, >= 0.

    Attributes
    ----------
    params : BladeParameters
        The parameters with the collective filled in (trimmed if it was None).
    mu : float
        Advance ratio.
    mass_properties : MassProperties
        Blade mass properties about the pitch hinge.
    r : numpy.ndarray
        Aerodynamic station radii (m, at zero hinge angles), shape ``(n_stations,)``.
    """

    def __init__(self, params: BladeParameters, mu: float = 0.0):
        mu = float(mu)
        if not (math.isfinite(mu) and mu >= 0):
            raise ValueError(f"mu must be a finite advance ratio >= 0, got {mu!r}")
        trimmed = None
        if params.collective is None:
            from .trim import hover_trim

            trimmed = hover_trim(params)
            params = replace(params, collective=trimmed.collective)
        self.params = params
        self.mu = mu
        self.omega = params.rotor_speed
        self.mass_properties = mass_properties(params)
        self._P = self._parameter_tuple()
        self._damping = np.array([params.flap_damping, params.lag_damping, params.pitch_damping])
        self._setup_stations()
        self._hover_equilibrium: FloatArray | None = (
            None if trimmed is None else np.array(trimmed.equilibrium, dtype=np.float64))

    def _with_collective(self, collective: float) -> "Blade":
        """A copy of this blade with another collective (shares the precomputed data)."""
        other = copy.copy(self)
        other.params = replace(self.params, collective=float(collective))
        other._hover_equilibrium = None
        return other

    # ------------------------------------------------------------------ set-up
    def _parameter_tuple(self) -> tuple[float, ...]:
        p, mp = self.params, self.mass_properties
        d = p.hub_element_lengths
        I = mp.inertia
        values = {
            "m": mp.mass, "S_x": mp.first_moment[0], "S_y": mp.first_moment[1],
            "S_z": mp.first_moment[2],
            "I_xx": I[0, 0], "I_yy": I[1, 1], "I_zz": I[2, 2],
            "I_xy": I[0, 1], "I_yz": I[1, 2], "I_xz": I[0, 2],
            "d_1": d[0], "d_2": d[1], "d_3": d[2], "d_4": d[3],
            "Omega": p.rotor_speed, "g": p.gravity,
            "K_beta": p.flap_stiffness, "K_zeta": p.lag_stiffness, "K_theta": p.pitch_stiffness,
            "k_3": p.pitch_flap_coupling,
        }
        return tuple(float(values[n]) for n in _gen.PARAMETER_NAMES)

    def _setup_stations(self) -> None:
        p = self.params
        ro, wo = p.stations()
        r = ro * p.radius
        self.r = r
        self.r_over_R = ro
        self.weights = wo * p.radius  # m
        c = p.chord_at(ro)
        phi = _twist(p, r)
        off = (p.pitch_axis - p.aerodynamic_centre_at(ro)) * c
        col = lambda a: np.ascontiguousarray(np.asarray(a, dtype=np.float64)[:, None])  # noqa: E731
        self._rho_x = r - p.pitch_hinge_radius
        self._rho_y = p.hub_element_lengths[4] + off * np.cos(phi)
        self._rho_z = off * np.sin(phi)
        self._rx, self._ry, self._rz = col(self._rho_x), col(self._rho_y), col(self._rho_z)
        # the point whose air velocity defines the relative wind (three-quarter chord)
        wind = p.aerodynamic_centre_at(ro) if p.wind_point is None else p.wind_point
        off_w = (p.pitch_axis - wind) * c
        self._wy = col(p.hub_element_lengths[4] + off_w * np.cos(phi))
        self._wz = col(off_w * np.sin(phi))
        self._phi = col(phi)
        self._qn = col(0.5 * p.air_density * c * self.weights)  # force factor x |w| w
        self._mn = col(0.5 * p.air_density * c * c * self.weights)  # moment factor x |w|^2
        # pitch-damping couple 0.5 rho U^2 c^2 cm_q (q c / 2U) = (rho c^3 cm_q / 4) U q
        self._dn = col(0.25 * p.air_density * p.cm_pitch_rate * c ** 3 * self.weights)
        self._pitch_damped = p.cm_pitch_rate != 0.0
        self._aero = p.air_density > 0.0
        # Induced inflow lambda_i(r, psi) = a(r) + b(r) cos psi (Glauert form, checked).
        from .inflow import induced_inflow

        VR = p.rotor_speed * p.radius
        lam_90 = np.asarray(induced_inflow(p, self.mu, ro, 0.5 * math.pi), dtype=np.float64)
        lam_0 = np.asarray(induced_inflow(p, self.mu, ro, 0.0), dtype=np.float64)
        lam_t = np.asarray(induced_inflow(p, self.mu, ro, 2.0), dtype=np.float64)
        a, b = lam_90, lam_0 - lam_90
        if not np.allclose(a + b * math.cos(2.0), lam_t, rtol=1e-12, atol=1e-14):
            raise ValueError("induced_inflow is not of the form lambda_0 (1 + k_x r cos psi)")
        self._inflow_a = col(-a * VR)  # z_H air velocity, m/s (downward inflow)
        self._inflow_b = col(-b * VR)
        self._inflow_uniform_in_psi = bool(np.all(b == 0.0))
        self._mu_VR = self.mu * VR

    # ------------------------------------------------------------------ controls
    def pitch_control(self, psi: ArrayLike) -> FloatArray:
        """Control pitch ``theta_c(psi) = collective + cyclic_cos cos psi + cyclic_sin sin psi``, rad."""
        p = self.params
        psi = np.asarray(psi, dtype=np.float64)
        if p.cyclic_cos == 0.0 and p.cyclic_sin == 0.0:
            return np.full(psi.shape, p.collective)
        return p.collective + p.cyclic_cos * np.cos(psi) + p.cyclic_sin * np.sin(psi)

    def pitch_control_rate(self, psi: ArrayLike) -> FloatArray:
        """``d theta_c / d psi``, rad/rad."""
        p = self.params
        psi = np.asarray(psi, dtype=np.float64)
        return -p.cyclic_cos * np.sin(psi) + p.cyclic_sin * np.cos(psi)

    # ------------------------------------------------------------------ kernels (flat, 1 block)
    def _wind(self, psi: FloatArray, T: FloatArray):
        """In-plane air velocity relative to the sections' wind points, B components, m/s.

        The wind point is ``params.wind_point`` (three-quarter chord by default): its velocity
        includes the pitch-rate term of quasi-steady thin-airfoil theory.

        ``T`` = rows of ``rhs_terms`` for one block; returns ``(u_y, u_z)``, each of shape
        (stations, n).
        """
        vPy, vPz, wx, wy, wz = T[10:15]
        C = T[33:42]
        # air velocity relative to the hub, H components: (mu VR cos psi, -mu VR sin psi, az)
        if self._inflow_uniform_in_psi:
            az = self._inflow_a
        else:
            az = self._inflow_a + self._inflow_b * np.cos(psi)
        if self._mu_VR != 0.0:
            ax = self._mu_VR * np.cos(psi)
            ay = -self._mu_VR * np.sin(psi)
            air_y = (C[3] * ax + C[4] * ay) + C[5] * az
            air_z = (C[6] * ax + C[7] * ay) + C[8] * az
        else:
            air_y = C[5] * az
            air_z = C[8] * az
        rx, ry, rz = self._rx, self._wy, self._wz
        u_y = air_y - (vPy + wz * rx - wx * rz)  # air relative to the section, B components
        u_z = air_z - (vPz + wx * ry - wy * rx)
        return u_y, u_z

    def _aero_loads(self, psi: FloatArray, T: FloatArray):
        """Strip loads for one block; ``T`` = rows of ``rhs_terms``.

        Returns the summed force (F_y, F_z) in B (N), the moment about the pitch hinge
        (M_x, M_y, M_z) in B (N m) and the section angle of attack (stations, n).
        """
        u_y, u_z = self._wind(psi, T)
        ry = self._ry
        rz = self._rz
        V2 = u_y * u_y + u_z * u_z
        Vm = np.sqrt(V2)
        alpha = np.arctan2(u_z, -u_y)
        if self.params.twist != 0.0:
            alpha = alpha + self._phi
        cl, cd, cm = self.params.airfoil.coefficients(alpha)
        qn = self._qn * Vm
        Fy = qn * (cd * u_y + cl * u_z)
        Fz = qn * (cd * u_z - cl * u_y)
        Mx_ac = self._mn * V2 * cm
        if self._pitch_damped:
            # pitch rate of the section relative to the hub frame H (which carries the
            # rotational relative wind): w_x - Omega (z_H . x_B), rad/s
            q_rel = T[12] - self.omega * T[35]
            Mx_ac = Mx_ac + self._dn * Vm * q_rel
        sFy = Fy.sum(axis=0)
        sFz = Fz.sum(axis=0)
        Mx = (ry * Fz - rz * Fy + Mx_ac).sum(axis=0)
        My = -(self._rho_x @ Fz)
        Mz = self._rho_x @ Fy
        return sFy, sFz, Mx, My, Mz, alpha

    @staticmethod
    def _project(T: FloatArray, sFy, sFz, Mx, My, Mz):
        """Generalised forces ``Pv^T F + Pw^T M`` (N m) from the summed loads."""
        Pv = T[15:24]
        Pw = T[24:33]
        return tuple(Pv[3 + k] * sFy + Pv[6 + k] * sFz + Pw[k] * Mx + Pw[3 + k] * My
                     + Pw[6 + k] * Mz for k in range(3))

    def _accelerations(self, psi: FloatArray, zc: FloatArray, T: FloatArray):
        """``q''`` (3 arrays) for one block from the generated rows ``T``."""
        om = self.omega
        F0, F1, F2 = T[6], T[7], T[8]
        c = self._damping * om
        F0 = F0 - c[0] * zc[3]
        F1 = F1 - c[1] * zc[4]
        F2 = F2 - c[2] * zc[5]
        if self._aero:
            loads = self._aero_loads(psi, T)
            Q = self._project(T, *loads[:5])
            F0, F1, F2 = F0 + Q[0], F1 + Q[1], F2 + Q[2]
        a0, a1, a2 = _solve_sym3(T[0:6], F0, F1, F2)
        s = 1.0 / (om * om)
        return a0 * s, a1 * s, a2 * s

    def _rhs_block(self, psi: FloatArray, zc: FloatArray) -> FloatArray:
        """rhs for one block: ``zc`` of shape (6, n); returns (6, n)."""
        T = _gen.rhs_terms(*zc, self.pitch_control(psi), self._P)
        out = np.empty_like(zc)
        out[:3] = zc[3:]
        out[3], out[4], out[5] = self._accelerations(psi, zc, T)
        return out

    def _blocks(self, psi: ArrayLike, z: ArrayLike, kernel, n_out: int):
        """Apply ``kernel(psi_block (n,), z_block (6, n)) -> (n_out, n)`` over blocks of states.

        Returns an array of shape ``broadcast(psi, z[..., 0]).shape + (n_out,)``.
        """
        pf, zf, shape = _flatten(psi, z)
        n = zf.shape[0]
        out = np.empty((n_out, n))
        for s in range(0, n, CHUNK):
            sl = slice(s, min(s + CHUNK, n))
            out[:, sl] = kernel(pf[sl], np.ascontiguousarray(zf[sl].T))
        return np.moveaxis(out, 0, -1).reshape(shape + (n_out,))

    # ------------------------------------------------------------------ public API
    def rhs(self, psi: ArrayLike, z: ArrayLike) -> FloatArray:
        """Right-hand side ``z' = h(psi, z)`` of the equations of motion.

        Parameters
        ----------
        psi : float or array_like
            Azimuth, rad; broadcasts with ``z.shape[:-1]``.
        z : array_like, shape (..., 6)
            State ``(beta, zeta, theta, beta', zeta', theta')``, rad and rad/rad.

        Returns
        -------
        numpy.ndarray, shape (..., 6)
            ``z'``: rates (rad/rad) and accelerations ``q''`` (rad/rad^2).
        """
        return self._blocks(psi, z, self._rhs_block, 6)

    def generalised_forces(self, psi: ArrayLike, z: ArrayLike) -> dict[str, FloatArray]:
        """Generalised forces on the three hinges, by kind, N m, each of shape (..., 3).

        Keys: ``"conservative"`` (inertial, gravity, springs: everything from the Lagrangian
        except the ``M q''`` term), ``"damping"``, ``"aerodynamic"``.
        """
        def kernel(psi_b, zc):
            T = _gen.rhs_terms(*zc, self.pitch_control(psi_b), self._P)
            out = np.zeros((9, zc.shape[1]))
            out[0:3] = T[6:9]
            out[3:6] = -(self._damping * self.omega)[:, None] * zc[3:]
            if self._aero:
                out[6:9] = self._project(T, *self._aero_loads(psi_b, T)[:5])
            return out

        r = self._blocks(psi, z, kernel, 9)
        return {"conservative": r[..., 0:3], "damping": r[..., 3:6], "aerodynamic": r[..., 6:9]}

    def aerodynamic_forces(self, psi: ArrayLike, z: ArrayLike) -> FloatArray:
        """Generalised aerodynamic forces on (beta, zeta, theta), N m, shape (..., 3)."""
        return self.generalised_forces(psi, z)["aerodynamic"]

    def blade_aerodynamic_force(self, psi: ArrayLike, z: ArrayLike) -> FloatArray:
        """Resultant aerodynamic force on the blade in ``H`` components (radial, in-plane
        towards the rotation direction, up), N, shape (..., 3)."""
        def kernel(psi_b, zc):
            T = _gen.rhs_terms(*zc, self.pitch_control(psi_b), self._P)
            out = np.zeros((3, zc.shape[1]))
            if self._aero:
                sFy, sFz = self._aero_loads(psi_b, T)[:2]
                C = T[33:42]  # b_i . h_j
                for j in range(3):
                    out[j] = C[3 + j] * sFy + C[6 + j] * sFz
            return out

        return self._blocks(psi, z, kernel, 3)

    def rotor_thrust(self, psi: ArrayLike, z: ArrayLike) -> FloatArray:
        """Rotor thrust ``n_blades`` x the blade's vertical (``+Z``) aerodynamic force, N."""
        return self.params.n_blades * self.blade_aerodynamic_force(psi, z)[..., 2]

    def angle_of_attack(self, psi: ArrayLike, z: ArrayLike) -> FloatArray:
        """Section angles of attack at the stations ``self.r``, rad, shape (..., n_stations).

        Full range, ``atan2`` convention: 0 for flow from the leading edge, +-pi in reverse
        flow; includes the pretwist.
        """
        def kernel(psi_b, zc):
            T = _gen.rhs_terms(*zc, self.pitch_control(psi_b), self._P)
            return self._aero_loads(psi_b, T)[5]

        return self._blocks(psi, z, kernel, len(self.r))

    def relative_wind(self, psi: ArrayLike, z: ArrayLike) -> FloatArray:
        """In-plane air velocity relative to each section's aerodynamic centre, m/s.

        Returns
        -------
        numpy.ndarray, shape (..., n_stations, 2)
            ``(w_y, w_z)`` in ``B`` components (``w_y < 0``: flow from the leading edge).
        """
        n_st = len(self.r)

        def kernel(psi_b, zc):
            T = _gen.rhs_terms(*zc, self.pitch_control(psi_b), self._P)
            u_y, u_z = self._wind(psi_b, T)
            return np.concatenate([u_y, u_z])

        out = self._blocks(psi, z, kernel, 2 * n_st)
        return np.stack([out[..., :n_st], out[..., n_st:]], axis=-1)

    def kinetic_energy(self, psi: ArrayLike, z: ArrayLike) -> FloatArray:
        """Kinetic energy of the blade in the inertial frame, ``T = T2 + T1 + T0``, J."""
        e = self._energies(psi, z)
        return e[..., 0] + e[..., 1] + e[..., 2]

    def kinetic_energy_parts(self, psi: ArrayLike, z: ArrayLike) -> FloatArray:
        """``(T2, T1, T0)``: the kinetic energy quadratic, linear and free in the rates, J,
        shape (..., 3)."""
        return self._energies(psi, z)[..., :3]

    def potential_energy(self, psi: ArrayLike, z: ArrayLike) -> FloatArray:
        """Potential energy ``V`` (hinge springs with the control input, and gravity), J."""
        return self._energies(psi, z)[..., 3]

    def effective_potential(self, psi: ArrayLike, z: ArrayLike) -> FloatArray:
        """Effective potential of the rotating frame ``U = V - T0`` (springs, gravity,
        centrifugal), J."""
        e = self._energies(psi, z)
        return e[..., 3] - e[..., 2]

    def _energies(self, psi, z):
        def kernel(psi_b, zc):
            return _gen.energies(*zc, self.pitch_control(psi_b), self._P)

        return self._blocks(psi, z, kernel, 4)

    def mass_matrix(self, z: ArrayLike) -> FloatArray:
        """Mass matrix ``M(q)`` of the time-domain equations, kg m^2, shape (..., 3, 3)."""
        def kernel(psi_b, zc):
            return _gen.rhs_terms(*zc, 0.0, self._P)[0:6]

        m6 = self._blocks(0.0, z, kernel, 6)
        idx = np.array([[0, 1, 2], [1, 3, 4], [2, 4, 5]])
        return m6[..., idx]

    def jacobian(self, psi: ArrayLike, z: ArrayLike, step: float = JACOBIAN_STEP) -> FloatArray:
        """Linearisation ``d h / d z`` of the right-hand side, shape (..., 6, 6).

        Central differences with step ``step`` (default :data:`JACOBIAN_STEP` = 1e-6 rad or
        rad/rad) in every state; truncation error ``~ step^2 |h'''| / 6`` and round-off
        ``~ eps |h| / step``, both about 1e-10 relative for this model.
        """
        z = np.asarray(z, dtype=np.float64)
        psi = np.asarray(psi, dtype=np.float64)
        E = np.eye(6) * step
        zp = np.concatenate([z[..., None, :] + E, z[..., None, :] - E], axis=-2)  # (..., 12, 6)
        f = self.rhs(psi[..., None], zp)
        return np.swapaxes((f[..., :6, :] - f[..., 6:, :]) / (2.0 * step), -1, -2)

    # ------------------------------------------------------------------ equilibrium
    def equilibrium(self, x0: ArrayLike | None = None, tol: float = 1e-10) -> FloatArray:
        """Hover equilibrium: hinge angles with zero rates where ``rhs = 0`` at ``mu = 0``.

        The controls are the blade's collective (the cyclic pitch is ignored: with cyclic there
        is no constant equilibrium).  This is the paper's steady motion, reused for every
        advance ratio.

        Parameters
        ----------
        x0 : array_like, shape (3,), optional
            Starting hinge angles, rad.  Default: continuation in the collective from the
            unloaded blade (zero collective), which selects the branch of equilibria connected
            to it; if the blade was trimmed (``collective=None``) the trimmed equilibrium is
            returned (it may lie past a fold of that branch, see :mod:`rotorlyap.trim`).
        tol : float
            Tolerance on the hinge angles, rad: the Newton correction at the solution (one
            Newton step with the finite-difference Jacobian is applied to the root found).

        Returns
        -------
        numpy.ndarray, shape (6,)
            ``(beta, zeta, theta, 0, 0, 0)``.

        Raises
        ------
        RuntimeError
            If the root finder does not converge (from ``x0``, or along the continuation).
        """
        if x0 is None and self._hover_equilibrium is not None:
            return self._hover_equilibrium.copy()
        from scipy.optimize import root

        p = self.params
        hover = self if (self.mu == 0.0 and p.cyclic_cos == 0.0 and p.cyclic_sin == 0.0) \
            else Blade(replace(p, cyclic_cos=0.0, cyclic_sin=0.0), mu=0.0)

        def newton_step(h: "Blade", q: FloatArray):
            zq = np.concatenate([q, np.zeros(3)])
            r = h.rhs(0.0, zq)[3:]
            J = h.jacobian(0.0, zq)[3:, :3]
            return np.linalg.solve(J, r)

        def solve(h: "Blade", start: FloatArray):
            """Newton's method (finite-difference Jacobian, steps limited to 0.1 rad); hybr
            from scipy if Newton fails.  Accepted when the Newton correction is < tol rad,
            which is scale-free (stiff springs make the residual large for tiny errors)."""
            q = np.array(start, dtype=np.float64)
            err = np.inf
            try:
                for _ in range(60):
                    dq = newton_step(h, q)
                    err = float(np.abs(dq).max())
                    q = q - dq * min(1.0, 0.1 / max(err, 1e-300))
                    if err < tol:
                        return q, "Newton converged", err
            except np.linalg.LinAlgError:
                pass
            sol = root(lambda u: h.rhs(0.0, np.concatenate([u, np.zeros(3)]))[3:], start,
                       method="hybr", options={"xtol": 1e-13})
            try:
                dq = newton_step(h, sol.x)
            except np.linalg.LinAlgError:
                return None, sol.message + " (singular Jacobian)", np.inf
            err = float(np.abs(dq).max())
            return (sol.x - dq if err < tol else None), sol.message, err

        messages = []
        if x0 is not None:
            q, msg, err = solve(hover, np.asarray(x0, dtype=np.float64))
            if q is None:
                messages.append(f"from {x0}: {msg} (Newton correction {err:.3g} rad)")
        else:
            # Continuation in the collective from the unloaded blade (zero collective), with
            # step halving; it follows the branch of equilibria connected to the unloaded blade.
            q, msg, err = solve(hover._with_collective(0.0), np.zeros(3))
            c, step, target = 0.0, 0.01, float(p.collective)
            if q is None:
                messages.append(f"no equilibrium at zero collective: {msg} (Newton correction {err:.3g} rad)")
            while q is not None and c != target:
                c_next = c + float(np.clip(target - c, -step, step))
                q_next, msg, err = solve(hover._with_collective(c_next), q)
                if q_next is None:
                    step *= 0.5
                    if step < 1e-4:
                        messages.append(
                            f"continuation from zero collective stopped at {c:.5f} rad "
                            f"(target {target:.5f} rad): {msg} (Newton correction {err:.3g} rad); the branch "
                            "of equilibria folds before the target collective. Trim the "
                            "collective (params.collective = None) or give x0.")
                        q = None
                    continue
                c, q = c_next, q_next
        if q is not None:
            z = np.concatenate([q, np.zeros(3)])
            if x0 is None:
                self._hover_equilibrium = z.copy()
            return z
        raise RuntimeError("hover equilibrium did not converge:\n  " + "\n  ".join(messages))

    # ------------------------------------------------------------------ energy function
    def energy_function(self, xi: ArrayLike | Callable | None = None,
                        dxi: Callable | None = None) -> "EnergyFunction":
        """The paper's Liapunov function (energy of the disturbed motion) about ``xi``.

        Parameters
        ----------
        xi : array_like (6,), callable or None
            Steady motion: a constant state (default: :meth:`equilibrium`), or a callable
            ``xi(psi) -> (..., 6)``, ``2 pi``-periodic.
        dxi : callable, optional
            ``dxi(psi) -> (..., 6)``, the derivative of a callable ``xi``; required with it.

        Returns
        -------
        EnergyFunction
        """
        if xi is None:
            xi = self.equilibrium()
        return EnergyFunction(self, xi, dxi)

    def quadratic_function(self, xi: ArrayLike | Callable | None = None, Q: ArrayLike | None = None,
                           dxi: Callable | None = None, **options):
        """A quadratic Liapunov function ``x^T P(psi) x`` about ``xi`` from the periodic Lyapunov
        equation of this blade linearised there; see
        :func:`rotorlyap.quadratic.quadratic_function` (same arguments; ``options`` are passed
        on: ``scales``, ``n_steps``, ``label``).

        Raises
        ------
        ValueError
            If the linearised blade is not asymptotically stable (no quadratic function exists).
        """
        from .quadratic import quadratic_function

        return quadratic_function(self, xi, Q, dxi, **options)

    # ------------------------------------------------------------------ kernels for W
    @property
    def has_cyclic(self) -> bool:
        """True if cyclic pitch is applied (the control input depends on psi)."""
        return self.params.cyclic_cos != 0.0 or self.params.cyclic_sin != 0.0

    def _potential_terms(self, psi: ArrayLike, q: ArrayLike) -> FloatArray:
        """Generated ``potential_terms`` at hinge angles ``q`` (3, ...) : rows first.

        Without cyclic pitch the control input is the scalar collective and ``psi`` is ignored.
        """
        thc = self.pitch_control(psi) if self.has_cyclic else self.params.collective
        return _gen.potential_terms(q[0], q[1], q[2], thc, self._P)


# --------------------------------------------------------------------------------------
# Energy (Liapunov) function
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class PositivityReport:
    """Local positivity of ``W`` at ``x = 0`` (condition (d) near the steady motion).

    Attributes
    ----------
    psi : numpy.ndarray
        Azimuths checked, rad.
    potential_eigenvalues : numpy.ndarray
        Eigenvalues of the Hessian of ``U`` at ``q_s(psi)``, J/rad^2, shape (n_psi, 3).
    kinetic_eigenvalues : numpy.ndarray
        Eigenvalues of ``Omega^2 M(q_s(psi))``, J/(rad/rad)^2, shape (n_psi, 3).
    positive_definite : bool
        All eigenvalues > 0: ``W`` has a strict local minimum 0 at ``x = 0`` for every psi.
    """

    psi: FloatArray
    potential_eigenvalues: FloatArray
    kinetic_eigenvalues: FloatArray
    positive_definite: bool

    def __str__(self) -> str:
        return (f"Hessian of W at x = 0: potential part eigenvalues in "
                f"[{self.potential_eigenvalues.min():.4g}, {self.potential_eigenvalues.max():.4g}] J/rad^2, "
                f"kinetic part in [{self.kinetic_eigenvalues.min():.4g}, "
                f"{self.kinetic_eigenvalues.max():.4g}] J; "
                + ("positive definite" if self.positive_definite else "NOT positive definite"))


@dataclass(frozen=True)
class EnergyFunction:
    """The energy of the disturbed motion, the paper's Liapunov function.

    For the disturbed state ``x = z - xi(psi)`` with ``q = q_s + x_q`` (``q_s = xi[:3]``) and
    the disturbed rates ``x_r = z[3:] - xi[3:]``,

        W(psi, x) = 1/2 Omega^2 x_r^T M(q) x_r + U(psi, q) - U(psi, q_s) - grad_q U(psi, q_s) . x_q,

    in J, with ``M`` the mass matrix (so the first term is the kinetic energy of the disturbance
    relative to the rotating hub) and ``U = V - T0`` the effective potential of the rotating
    frame (hinge springs with the control input and pitch-flap coupling, gravity and the
    centrifugal potential).  The linear term shifts ``U`` so that ``W(psi, 0) = 0`` and
    ``grad W(psi, 0) = 0`` even when ``q_s`` is not a conservative equilibrium (with
    aerodynamics the steady motion is held by the air loads, ``grad U(q_s) = Q_aero(q_s)``).
    In vacuum without dampers and with ``xi`` the equilibrium, ``W`` is Jacobi's integral
    ``T2 + U`` minus its value at rest, so ``W' = 0`` exactly.

    The derivative along the motion, ``W' = dW/dpsi + grad_x W . f(psi, x)`` with
    ``f = rhs(psi, xi + x) - xi'``, is computed analytically from generated code::

        grad_xq W = 1/2 Omega^2 x_r^T (dM/dq) x_r + grad U(q) - grad U(q_s),
        grad_xr W = Omega^2 M(q) x_r,
        dW/dpsi   = [1/2 Omega^2 x_r^T dM/dq x_r + grad U(q) - grad U(q_s)] . q_s'
                    - (Hess U(q_s) q_s') . x_q
                    + theta_c' [dU/dtheta_c(q) - dU/dtheta_c(q_s) - grad dU/dtheta_c(q_s) . x_q],

    where ``q_s' = xi'[:3]`` and ``theta_c'`` is the rate of the control input (the only
    explicit dependence of ``U`` on psi; ``dU/dtheta_c`` is affine in ``q``, so the last
    bracket vanishes identically and is kept only for generality).

    Conditions of the theorem (Narkiewicz & Lucjanek, section 2), on ``||x|| < H``:


    * (c) continuity and differentiability: ``W`` is analytic in ``x`` and ``psi`` (polynomial in
      the rates, trigonometric in the angles) for every state.

    * (d) positivity: ``W(psi, 0) = 0``, ``grad W(psi, 0) = 0``; ``W > 0`` for small ``x != 0``
      iff ``M(q_s)`` (always) and ``Hess U(q_s)`` are positive definite:
      :meth:`positivity` checks this.  Globally, ``W`` is not positive on every ball: the
      centrifugal potential is periodic in the angles and has other stationary points, so
      ``H`` must stay below the first of them (checked numerically by sampling, not here).

    * (e), (f) periodicity of ``W`` and its first derivatives: ``M`` and ``U`` depend on psi only
      through ``theta_c(psi)`` and ``xi(psi)``, both ``2 pi``-periodic.

    * (g) a property of the sphere extrema of ``W``, checked by the algorithm itself
      (:func:`rotorlyap.lyapunov.technical_stability`).

    Attributes
    ----------
    blade : Blade
    xi : numpy.ndarray or callable
        Steady motion.
    dxi : callable or None
        Its psi-derivative (None for a constant ``xi``).
    """

    blade: Blade
    xi: object
    dxi: object = None
    _const: FloatArray | None = field(init=False, repr=False, compare=False, default=None)
    _ps_const: FloatArray | None = field(init=False, repr=False, compare=False, default=None)

    def __post_init__(self) -> None:
        if callable(self.xi):
            if not callable(self.dxi):
                raise ValueError("a callable steady motion xi(psi) needs its derivative dxi(psi)")
            object.__setattr__(self, "_const", None)
        else:
            xi = np.asarray(self.xi, dtype=np.float64)
            if xi.shape != (6,):
                raise ValueError(f"a constant steady motion xi must have shape (6,), got {xi.shape}")
            object.__setattr__(self, "xi", xi)
            object.__setattr__(self, "_const", xi)
            object.__setattr__(self, "dxi", None)

    # ------------------------------------------------------------------ helpers
    def steady(self, psi: ArrayLike) -> tuple[FloatArray, FloatArray]:
        """``xi(psi)`` and ``xi'(psi)``, each broadcastable to (..., 6)."""
        if self._const is not None:
            return self._const, np.zeros(6)
        psi = np.asarray(psi, dtype=np.float64)
        return (np.asarray(self.xi(psi), dtype=np.float64),
                np.asarray(self.dxi(psi), dtype=np.float64))

    def _steady_block(self, psi: FloatArray):
        """xi, xi' as (6, n) or (6, 1) arrays and the potential terms at q_s (rows first)."""
        xi, dxi = self.steady(psi)
        xi = np.asarray(xi).T.reshape(6, -1)
        dxi = np.asarray(dxi).T.reshape(6, -1)
        b = self.blade
        if self._const is not None and not b.has_cyclic:
            if self._ps_const is None:
                object.__setattr__(self, "_ps_const", b._potential_terms(0.0, xi[:3]))
            ps = self._ps_const
        else:
            ps = b._potential_terms(psi, xi[:3])
        return xi, dxi, ps

    # ------------------------------------------------------------------ public
    def f(self, psi: ArrayLike, x: ArrayLike) -> FloatArray:
        """Disturbed right-hand side ``f(psi, x) = h(psi, xi + x) - xi'(psi)``, shape (..., 6)."""
        b = self.blade

        def kernel(psi_b, xc):
            xi, dxi, _ = self._steady_block(psi_b)
            return b._rhs_block(psi_b, xc + xi) - dxi

        return b._blocks(psi, x, kernel, 6)

    def W(self, psi: ArrayLike, x: ArrayLike) -> FloatArray:
        """Liapunov function ``W(psi, x)``, J, shape ``x.shape[:-1]`` (broadcast with psi)."""
        b = self.blade

        def kernel(psi_b, xc):
            xi, _, ps = self._steady_block(psi_b)
            q = xi[:3] + xc[:3]
            thc = b.pitch_control(psi_b)
            kin, U = _gen.w_terms(*q, *xc[3:], thc, b._P)
            return (kin + U - ps[0] - (ps[1:4] * xc[:3]).sum(axis=0))[None]

        return b._blocks(psi, x, kernel, 1)[..., 0]

    def dW(self, psi: ArrayLike, x: ArrayLike) -> FloatArray:
        """Derivative of ``W`` along the motion, ``W' = dW/dpsi + grad W . f``, J/rad.

        Analytic (generated code), no finite differences; shape ``x.shape[:-1]``.
        """
        return self.blade._blocks(psi, x, self._dw_block, 1)[..., 0]

    def _dw_block(self, psi: FloatArray, xc: FloatArray) -> FloatArray:
        """W' for one block of disturbed states ``xc`` (6, n)."""
        b = self.blade
        om2 = b.omega * b.omega
        xi, dxi, ps = self._steady_block(psi)
        zc = xc + xi
        xq, xr = xc[:3], xc[3:]
        gU_s = ps[1:4]
        thc = b.pitch_control(psi)
        T = _gen.rhs_dw_terms(*zc, thc, *xr, b._P)
        a = b._accelerations(psi, zc, T)
        dT2 = T[42:45]
        gU = T[45:48]
        gq = dT2 + gU - gU_s  # grad_xq W
        mx = _sym3_matvec(T[0:6], xr[0], xr[1], xr[2])  # M x_r
        dW = (gq[0] * (zc[3] - dxi[0]) + gq[1] * (zc[4] - dxi[1]) + gq[2] * (zc[5] - dxi[2])
              + om2 * (mx[0] * (a[0] - dxi[3]) + mx[1] * (a[1] - dxi[4]) + mx[2] * (a[2] - dxi[5])))
        if self._const is None:  # explicit psi-dependence through q_s(psi)
            hq = _sym3_matvec(ps[4:10], dxi[0], dxi[1], dxi[2])
            dW = dW + ((dT2 + gU - gU_s) * dxi[0:3]).sum(axis=0) \
                - (hq[0] * xq[0] + hq[1] * xq[1] + hq[2] * xq[2])
        if b.has_cyclic:  # explicit psi-dependence through theta_c(psi)
            dthc = b.pitch_control_rate(psi)
            dW = dW + dthc * (T[48] - ps[10] - (ps[11:14] * xq).sum(axis=0))
        return dW[None]

    def positivity(self, n_psi: int = 36) -> PositivityReport:
        """Check that the Hessian of ``W`` at ``x = 0`` is positive definite (condition (d)).

        The Hessian is block diagonal: ``Hess U(psi, q_s)`` for the displacements and
        ``Omega^2 M(q_s)`` for the rates.

        Parameters
        ----------
        n_psi : int
            Number of azimuths on ``[0, 2 pi)``.

        Returns
        -------
        PositivityReport
        """
        psi = np.linspace(0.0, 2.0 * np.pi, n_psi, endpoint=False)
        xi, _ = self.steady(psi)
        xi = np.broadcast_to(xi, (n_psi, 6))
        ps = np.broadcast_to(self.blade._potential_terms(psi, xi[:, :3].T).T, (n_psi, 14))
        idx = np.array([[0, 1, 2], [1, 3, 4], [2, 4, 5]])
        H = ps[:, 4:10][:, idx]
        M = self.blade.mass_matrix(xi) * self.blade.omega ** 2
        eu = np.linalg.eigvalsh(H)
        ek = np.linalg.eigvalsh(M)
        return PositivityReport(psi=psi, potential_eigenvalues=eu, kinetic_eigenvalues=ek,
                                positive_definite=bool((eu > 0).all() and (ek > 0).all()))
