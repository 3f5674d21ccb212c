"""Quasi-steady strip aerodynamics of the blade, with the pitch-damping couple and the inflow.

Quasi-steady 2-D strips at ``params.n_stations`` Gauss-Legendre stations on ``[R - R1, R]``.
At each station the air velocity relative to the section's wind point, in blade components,
is ``w = C_BH a_H - v`` with the air velocity relative to the hub ``a_N = (mu Omega R, 0,
-(lambda_i + mu tan alpha_s) Omega R)`` (``alpha_s`` = ``params.shaft_tilt``, the forward tilt of
the shaft; ``mu`` is the in-plane advance ratio) (``a_H = (mu Omega R cos psi, -mu Omega R sin psi, -lambda_i Omega R)``)
and ``v = v_P + omega x rho`` the inertial velocity of the wind point. Only the in-plane
components ``(w_y, w_z)`` are used (no radial flow effects). The angle of attack is
``alpha = atan2(w_z, -w_y) + phi(r)`` over the full circle, with ``phi`` the pretwist; lift
``dL = q c cl`` acts along ``(d_z, -d_y)``, drag ``dD = q c cd`` along the unit in-plane wind
``d = (w_y, w_z)/|w|`` and the moment ``q c^2 cm`` about ``x_B`` at the aerodynamic centre
(``q = rho |w|^2 / 2``). The pretwist ``phi(r) = twist (r - (R - R1)) / R1`` is zero at the
blade root, so the collective is the pitch of the root section.

The pitch-damping couple of quasi-steady thin-airfoil theory,
``0.5 rho U^2 c^2 cm_q (q c / 2U) = (rho c^3 cm_q / 4) U q``, acts about ``x_B`` with ``q`` the
pitch rate of the section relative to the hub frame (``BladeParameters.cm_pitch_rate``).

With ``params.compressibility = "prandtl-glauert"`` the section coefficients are corrected by
the section Mach number ``|w| / params.speed_of_sound`` (forward-flow lift, moment and
pitch-damping couple times the Prandtl-Glauert factor, capped at M = 0.8; Lock's drag rise above
Korn's critical Mach number): :mod:`rotorlyap.model.compressibility`. With ``"none"`` (default) the loads are the
incompressible ones, bit for bit. With ``"table"`` (a Mach-dependent C81 section,
:class:`rotorlyap.model.c81.C81Section`) the section is read at its Mach number
``|w| (1/params.speed_of_sound)`` (``coefficients(alpha, mach)``, bilinear in the angle and the Mach
number) and nothing is applied on top: the table holds the section's compressibility; the
pitch-damping couple takes no Mach factor. These loads run on the numpy path only (the compiled
kernels have no Mach axis; :mod:`rotorlyap.model.compiled` falls back here).

The induced inflow ``lambda_i(r, psi) = a(r) + b(r) cos psi`` comes from
:func:`rotorlyap.model.inflow.induced_inflow`, sampled once at construction (its form is checked).

The kernels take the rows ``T`` of the generated ``rhs_terms`` (pitch-hinge velocity, angular
velocity and direction cosines of the blade, :mod:`rotorlyap.model.derivation`) for one block
of states, and work on arrays of shape (stations, n).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from .compressibility import CompressibilityConstants, apply_to_coefficients, compressibility_constants
from .inflow import induced_inflow
from .mass import pretwist
from .parameters import BladeParameters

__all__ = ["StripAerodynamics"]

FloatArray = NDArray[np.float64]


def _column(a) -> FloatArray:
    return np.ascontiguousarray(np.asarray(a, dtype=np.float64)[:, None])


class StripAerodynamics:
    """The strip loads of one blade at one advance ratio.

    Parameters
    ----------
    params : BladeParameters
        The blade (its collective is not used here).
    mu : float
        Advance ratio, >= 0.

    Attributes
    ----------
    r : numpy.ndarray
        Station radii (m, at zero hinge angles), shape ``(n_stations,)``.
    r_over_R : numpy.ndarray
        The same as fractions of the radius.
    weights : numpy.ndarray
        Quadrature weights of the stations, m.
    active : bool
        False in vacuum (``air_density = 0``): no loads at all.
    compressibility : rotorlyap.model.compressibility.CompressibilityConstants
        The compressibility model's numbers (``compressibility.enabled`` False: none).
    """

    def __init__(self, params: BladeParameters, mu: float):
        p = params
        self.params = params
        self.mu = mu
        self.omega = p.rotor_speed
        ro, wo = p.stations()
        r = ro * p.radius
        self.r = r
        self.r_over_R = ro
        self.weights = wo * p.radius  # m
        c = p.chord_at(ro)
        phi = pretwist(p, r)
        off = (p.pitch_axis - p.aerodynamic_centre_at(ro)) * c
        self.rho_x = r - p.pitch_hinge_radius
        self._ry = _column(p.hub_element_lengths[4] + off * np.cos(phi))
        self._rz = _column(off * np.sin(phi))
        self._rx = _column(self.rho_x)
        # the point whose air velocity defines the relative wind (three-quarter chord)
        wind = p.aerodynamic_centre_at(ro) if p.wind_point is None else p.wind_point
        off_w = (p.pitch_axis - wind) * c
        self._wy = _column(p.hub_element_lengths[4] + off_w * np.cos(phi))
        self._wz = _column(off_w * np.sin(phi))
        self._phi = _column(phi)
        self._qn = _column(0.5 * p.air_density * c * self.weights)  # force factor x |w| w
        self._mn = _column(0.5 * p.air_density * c * c * self.weights)  # moment factor x |w|^2
        # pitch-damping couple 0.5 rho U^2 c^2 cm_q (q c / 2U) = (rho c^3 cm_q / 4) U q
        self._dn = _column(0.25 * p.air_density * p.cm_pitch_rate * c ** 3 * self.weights)
        self._pitch_damped = p.cm_pitch_rate != 0.0
        self.active = p.air_density > 0.0
        self.compressibility: CompressibilityConstants = compressibility_constants(p)
        # Induced inflow lambda_i(r, psi) = a(r) + b(r) cos psi (Glauert form, checked).
        VR = p.rotor_speed * p.radius
        lam_90 = np.asarray(induced_inflow(p, mu, ro, 0.5 * math.pi), dtype=np.float64)
        lam_0 = np.asarray(induced_inflow(p, mu, ro, 0.0), dtype=np.float64)
        lam_t = np.asarray(induced_inflow(p, mu, ro, 2.0), dtype=np.float64)
        a, b = lam_90, lam_0 - lam_90
        if not np.allclose(a + b * math.cos(2.0), lam_t, rtol=1e-12, atol=1e-14):
            raise ValueError("induced_inflow is not of the form lambda_0 (1 + k_x r cos psi)")
        # z_H air velocity, m/s: the induced inflow and, for a shaft tilted forward, the free
        # stream's part through the disc, mu tan(shaft_tilt) (the in-plane part is mu Omega R)
        self._inflow_a = _column(-(a + mu * math.tan(p.shaft_tilt)) * VR)
        self._inflow_b = _column(-b * VR)
        self._inflow_uniform_in_psi = bool(np.all(b == 0.0))
        self._mu_VR = mu * VR

    def kernel_inputs(self) -> tuple[FloatArray, float, bool, bool]:
        """The numbers of the compiled kernels (:mod:`rotorlyap.model.compiled`).

        Returns
        -------
        stations : numpy.ndarray, shape (11, n_stations)
            Rows: radius from the pitch hinge (m); the wind point's lever arms ``y``, ``z`` (m);
            the aerodynamic centre's lever arms ``y``, ``z`` (m); pretwist (rad); the force,
            moment and pitch-damping factors; the inflow coefficients ``a``, ``b`` (m/s).
        free_stream : float
            ``mu Omega R``, m/s.
        pitch_damped, inflow_uniform : bool
            The pitch-damping couple is on; the inflow does not depend on ``psi``.
        """
        rows = (self._rx, self._wy, self._wz, self._ry, self._rz, self._phi, self._qn, self._mn,
                self._dn, self._inflow_a, self._inflow_b)
        stations = np.ascontiguousarray(np.concatenate(rows, axis=1).T)
        return stations, float(self._mu_VR), bool(self._pitch_damped), bool(self._inflow_uniform_in_psi)

    def wind(self, psi: FloatArray, T: FloatArray):
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

    def loads(self, psi: FloatArray, T: FloatArray):
        """Strip loads for one block; ``T`` = rows of ``rhs_terms``.

        Returns the summed force (F_y, F_z) in B (N), the moment about the pitch hinge
        (M_x, M_y, M_z) in B (N m) and the section angle of attack (stations, n), rad.
        """
        u_y, u_z = self.wind(psi, T)
        ry = self._ry
        rz = self._rz
        V2 = u_y * u_y + u_z * u_z
        Vm = np.sqrt(V2)
        alpha = np.arctan2(u_z, -u_y)
        if self.params.twist != 0.0:
            alpha = alpha + self._phi
        if self.compressibility.section_mach:
            # the section's own Mach dependence (compressibility = "table"): no correction on top
            cl, cd, cm = self.params.airfoil.coefficients(alpha, Vm * self.compressibility.inverse_speed_of_sound)
        else:
            cl, cd, cm = self.params.airfoil.coefficients(alpha)
        pg = None
        if self.compressibility.enabled:
            cl, cd, cm, pg = apply_to_coefficients(alpha, Vm, cl, cd, cm, self.compressibility)
        qn = self._qn * Vm
        Fy = qn * (cd * u_y + cl * u_z)
        Fz = qn * (cd * u_z - cl * u_y)
        Mx_ac = self._mn * V2 * cm
        if self._pitch_damped:
            couple = self.pitch_damping_couple(T, Vm)
            Mx_ac = Mx_ac + (couple if pg is None else couple * pg)
        sFy = Fy.sum(axis=0)
        sFz = Fz.sum(axis=0)
        Mx = (ry * Fz - rz * Fy + Mx_ac).sum(axis=0)
        My = -(self.rho_x @ Fz)
        Mz = self.rho_x @ Fy
        return sFy, sFz, Mx, My, Mz, alpha

    def pitch_damping_couple(self, T: FloatArray, speed: FloatArray) -> FloatArray:
        """The quasi-steady pitch-damping couple of each strip about ``x_B``, N m, (stations, n).

        ``(rho c^3 cm_q / 4) U q`` per unit span times the station weight, with ``U`` the
        section's air speed ``speed`` (m/s) and ``q`` its pitch rate relative to the hub frame
        ``H`` (which carries the rotational relative wind): ``w_x - Omega (z_H . x_B)``, rad/s.
        """
        q_rel = T[12] - self.omega * T[35]
        return self._dn * speed * q_rel
