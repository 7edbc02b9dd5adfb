"""Closed forms of the Mohr-Coulomb verification problems (small strain, perfect plasticity).

Inside this module stresses are COMPRESSION POSITIVE (as in the soil mechanics texts the
formulas come from); the drivers convert from poroseam's tension-positive outputs.

Strip footing on a weightless soil (no surcharge), smooth or rough, associated flow:
    q_u = N_c c,  N_c = pi + 2 (Tresca, phi = 0; Prandtl 1920),
    N_c = (N_q - 1) cot(phi),  N_q = exp(pi tan phi) tan^2(pi/4 + phi/2) (Prandtl-Reissner).

Cylindrical cavity expanded from radius a in plane strain, Mohr-Coulomb soil (c, phi, psi <=
phi), isotropic initial stress p0 (also along the axis), outer radius b finite (traction p0 or
fixed), small strain: the solution of Carter, Booker and Yeung (1986, Geotechnique 36(3)) and
of Yu and Houlsby (1991, Geotechnique 41(2)) in its small-strain form, derived below for a
finite outer radius (the assumptions are theirs: the axial stress stays the intermediate
principal stress, which `CylindricalCavity.state` checks, so the plastic zone a <= r <= R is on
the one Mohr-Coulomb face sigma_r = N sigma_theta + 2 c sqrt(N), N = (1 + sin phi) /
(1 - sin phi)).
  Elastic zone R <= r <= b: d sigma_r = A + B / r^2, d sigma_theta = A - B / r^2 (increments
      from p0), A = kappa B with kappa = -1 / b^2 (outer traction p0) or 1 / ((1 - 2 nu) b^2)
      (outer wall fixed); yield at r = R fixes B = (p0 sin phi + c cos phi) / (1 / R^2 -
      kappa sin phi); u(R) = (1 + nu) / E (-(1 - 2 nu) A R + B / R).
  Plastic zone: equilibrium with the yield condition gives sigma_r + c cot phi = (sigma_R +
      c cot phi) (R / r)^((N - 1) / N) (phi = 0: sigma_r = sigma_R + 2 c ln(R / r)); the cavity
      pressure is sigma_r(a).
  Displacement: the plastic strains of the face, in the ratio eps_theta^p / eps_r^p = -M,
      M = (1 + sin psi) / (1 - sin psi), cancel in M eps_r + eps_theta, so M u' + u / r =
      M eps_r^e + eps_theta^e (plane-strain elastic strains of the stress increments, known
      in closed form), integrated from u(R) inwards with the factor r^(1/M):
      u(a) = a^(-1/M) [R^(1/M) u(R) - int_a^R r^(1/M) (M eps_r^e + eps_theta^e) / M dr]
      (the integrand is a sum of powers of r; evaluated by Gauss-Legendre quadrature, exact to
      round-off).
The pressure-expansion curve p(u_a) follows by solving u(a; R) = u_a for R (bisection, u(a)
grows with R).
"""

import math
import sys

import numpy as np


def prandtl_bearing_factor(phi_deg):
    """N_c of a strip footing on a weightless soil (associated flow)."""
    if phi_deg == 0.0:
        return math.pi + 2.0
    phi = math.radians(phi_deg)
    nq = math.exp(math.pi * math.tan(phi)) * math.tan(math.pi / 4 + phi / 2) ** 2
    return (nq - 1.0) / math.tan(phi)


class CylindricalCavity:
    """Small-strain expansion of a cylindrical cavity in Mohr-Coulomb soil (compression
    positive, displacements outward positive)."""

    def __init__(self, E, nu, c, phi_deg, psi_deg, p0, a, b, outer="traction"):
        self.E, self.nu, self.c, self.p0, self.a, self.b = E, nu, c, p0, a, b
        self.phi, self.psi = math.radians(phi_deg), math.radians(psi_deg)
        sp = math.sin(self.phi)
        self.N = (1 + sp) / (1 - sp)
        self.M = (1 + math.sin(self.psi)) / (1 - math.sin(self.psi))
        if outer == "traction":
            self.kappa = -1.0 / b**2
        elif outer == "fixed":
            self.kappa = 1.0 / ((1 - 2 * nu) * b**2)
        else:
            raise ValueError(f"outer must be 'traction' or 'fixed', got {outer!r}")
        self.nodes, self.weights = np.polynomial.legendre.leggauss(64)

    def _elastic_zone(self, R):
        """B, sigma_r(R), u(R) when the elastic-plastic boundary is at R."""
        sp, cp = math.sin(self.phi), math.cos(self.phi)
        B = (self.p0 * sp + self.c * cp) / (1.0 / R**2 - self.kappa * sp)
        A = self.kappa * B
        sigma_R = self.p0 + A + B / R**2
        u_R = (1 + self.nu) / self.E * (-(1 - 2 * self.nu) * A * R + B / R)
        return B, sigma_R, u_R

    def stresses(self, r, R):
        """sigma_r, sigma_theta, sigma_z in the plastic zone a <= r <= R (arrays)."""
        _, sigma_R, _ = self._elastic_zone(R)
        r = np.asarray(r, dtype=float)
        if self.phi == 0.0:
            sr = sigma_R + 2 * self.c * np.log(R / r)
            st = sr - 2 * self.c
        else:
            cc = self.c / math.tan(self.phi)
            s = (sigma_R + cc) * (R / r) ** ((self.N - 1) / self.N)
            sr, st = s - cc, s / self.N - cc
        sz = self.p0 + self.nu * (sr - self.p0 + st - self.p0)
        return sr, st, sz

    def state(self, R):
        """(cavity pressure, cavity wall displacement, axial stress intermediate?) for the
        plastic radius R >= a."""
        a, E, nu, M, p0 = self.a, self.E, self.nu, self.M, self.p0
        _, _, u_R = self._elastic_zone(R)
        r = 0.5 * (R - a) * self.nodes + 0.5 * (R + a)
        sr, st, sz = self.stresses(r, R)
        dr, dt = sr - p0, st - p0
        # Plane-strain elastic strains (extension positive) of compressive increments.
        er = -((1 - nu**2) * dr - nu * (1 + nu) * dt) / E
        et = -((1 - nu**2) * dt - nu * (1 + nu) * dr) / E
        integral = 0.5 * (R - a) * np.sum(self.weights * r ** (1 / M) * (M * er + et) / M)
        u_a = a ** (-1 / M) * (R ** (1 / M) * u_R - integral)
        sr_a, st_a, sz_a = self.stresses(np.array([a, R]), R)
        intermediate = bool(np.all(st_a <= sz_a + 1e-9 * abs(sr_a[0])) and
                            np.all(sz_a <= sr_a + 1e-9 * abs(sr_a[0])))
        return float(sr_a[0]), float(u_a), intermediate

    def yield_displacement(self):
        return self.state(self.a)[1]

    def pressure(self, u_a):
        """Cavity pressure for the wall displacement u_a >= 0, and the plastic radius (a when
        elastic)."""
        u_y = self.yield_displacement()
        if u_a <= u_y:
            p_y = self.state(self.a)[0]
            return self.p0 + (p_y - self.p0) * u_a / u_y, self.a
        lo, hi = self.a, self.a
        while self.state(hi)[1] < u_a:
            lo, hi = hi, hi * 1.5
            if hi > self.b:
                raise ValueError(f"u_a = {u_a} m reaches the outer radius: no closed form")
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if self.state(mid)[1] < u_a:
                lo = mid
            else:
                hi = mid
            if hi - lo < 1e-13 * self.a:
                break
        R = 0.5 * (lo + hi)
        p, _, intermediate = self.state(R)
        if not intermediate:
            raise ValueError(f"u_a = {u_a} m: the axial stress is no longer intermediate, the "
                             "closed form (one Mohr-Coulomb face) does not apply")
        return p, R


if __name__ == "__main__":
    # Self-checks of the algebra against independent results: Prandtl's numbers, the first
    # yield of a cavity in an infinite medium (p0 (1 + sin phi) + c cos phi), the classical
    # incompressible Tresca solution p = c (1 + ln(2 G u_a / (c a))) (small strain, nu -> 1/2,
    # b -> infinity), and the Tresca limit phi -> 0 of the frictional formulas.
    def close(name, got, want, rtol):
        ok = abs(got - want) <= rtol * abs(want)
        print(f"{'ok  ' if ok else 'FAIL'} {name}: {got:.10g} (expected {want:.10g})")
        return ok

    checks = [close("N_c(0)", prandtl_bearing_factor(0.0), math.pi + 2, 1e-15),
              close("N_c(20 deg)", prandtl_bearing_factor(20.0), 14.8347, 1e-5),
              close("N_c(30 deg)", prandtl_bearing_factor(30.0), 30.1396, 1e-5)]
    deep = CylindricalCavity(1e7, 0.3, 1e4, 30, 10, 1e5, 1.0, 1e7)
    checks.append(close("first yield, p0 = 100 kPa", deep.state(1.0)[0],
                        1e5 * 1.5 + 1e4 * math.cos(math.radians(30)), 1e-9))
    nu = 0.4999999
    G = 1e7 / (2 * (1 + nu))
    tresca = CylindricalCavity(1e7, nu, 1e4, 0, 0, 0.0, 1.0, 1e7)
    for u in (0.005, 0.02):
        checks.append(close(f"incompressible Tresca, u_a = {u}", tresca.pressure(u)[0],
                            1e4 * (1 + math.log(2 * G * u / 1e4)), 1e-6))
    t0 = CylindricalCavity(1e7, 0.3, 1e4, 0, 0, 0.0, 1.0, 1e3)
    t1 = CylindricalCavity(1e7, 0.3, 1e4, 1e-7, 0, 0.0, 1.0, 1e3)
    checks.append(close("phi -> 0 limit, u_a = 0.01", t1.pressure(0.01)[0], t0.pressure(0.01)[0],
                        1e-6))
    sys.exit(0 if all(checks) else 1)
