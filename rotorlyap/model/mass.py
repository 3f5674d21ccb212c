"""Mass properties of the rigid blade about its pitch hinge, from the spanwise distribution.

The blade body carries the blade's mass, first moment and inertia tensor into the equations
of motion (:mod:`rotorlyap.model.derivation` writes them as parameters of the generated code);
the pretwist places each section's chord, hence its C.G. and its aerodynamic centre.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .parameters import BladeParameters, gauss_legendre

__all__ = ["MassProperties", "mass_properties", "pretwist"]

FloatArray = NDArray[np.float64]


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


def pretwist(params: BladeParameters, r: FloatArray) -> FloatArray:
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
    x, w = gauss_legendre(n_points)
    a, b = params.root_cutout, params.radius
    r = 0.5 * (b - a) * x + 0.5 * (b + a)
    dr = 0.5 * (b - a) * w
    ro = r / params.radius
    dm = params.mass_per_length_at(ro) * dr
    c = params.chord_at(ro)
    phi = pretwist(params, r)
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
