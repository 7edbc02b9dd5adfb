"""Closed-form solutions of Biot consolidation used by the verification tests and scripts/study.

Conventions (the same as poroseam, docs/physics.md sections 1 and 2): tension-positive stress, absolute
pore pressure p (no gravity here), Biot coefficient ``alpha``, storage ``S = 1/M``, mobility
``kappa = k / mu_w`` (intrinsic permeability over water viscosity).  Mass balance
``alpha d(div u)/dt + S dp/dt + div q = 0``, ``q = -kappa grad p``.

Only numpy (and the standard library) is needed.  Run ``python3 analytic.py`` for the
self-check.

Terzaghi (1D consolidation)
    Column of height H, bottom fixed and impervious, top drained (p = 0) and loaded by a
    compressive traction q > 0 (a step load at t = 0+).  z is the depth measured from the
    drained top.  Undrained response at t = 0+ (no fluid exchanged, alpha eps + S p = 0;
    equilibrium M_c eps - alpha p = -q):

        p0   = alpha q / (alpha^2 + S M_c),          eps0 = -S p0 / alpha
        c_v  = kappa M_c / (alpha^2 + S M_c),        T = c_v t / H^2
        p(z, t) = p0 sum_m (2 / M_m) sin(M_m z / H) exp(-M_m^2 T),   M_m = pi (2m + 1) / 2
        s(t) = u_top(t) = -q H / M_c + (alpha / M_c) int_0^H p dz
             = -q H / M_c + (alpha p0 H / M_c) sum_m (2 / M_m^2) exp(-M_m^2 T)

    With alpha = 1, S = 0: p0 = q, c_v = kappa M_c and s = -(q H / M_c)(1 - sum 2/M_m^2 e^..).

    Backward Euler in time (continuous in space): the coupled 1D system with the load on from
    the first step reduces exactly to backward Euler on the diffusion equation started from
    p0, so every Fourier mode is multiplied by 1 / (1 + M_m^2 c_v dt_i / H^2) at each step i
    instead of exp(-M_m^2 c_v dt_i / H^2).  ``terzaghi_*_be`` take the list of step end times
    (uniform or not) and return that semi-discrete solution, so that comparing a finite-
    element run with it measures the spatial error alone.

Mandel (plane strain, Cheng & Detournay 1988, Abousleiman et al. 1996)
    Specimen -a <= x <= a, -b <= y <= b between rigid frictionless plates that each push with
    a force 2F per unit thickness (F on a quarter model); lateral sides x = +-a drained and
    traction free.  With the drained Poisson ratio nu, undrained nu_u and Skempton B
    (alpha = 1 and incompressible constituents: B = 1, nu_u = 1/2):

        tan(alpha_i) = (1 - nu) / (nu_u - nu) alpha_i,   alpha_i in ((i-1) pi, (i-1/2) pi)
        c = 2 kappa B^2 G (1 - nu)(1 + nu_u)^2 / (9 (1 - nu_u)(nu_u - nu))
        p(x, t) = 2 p0 sum_i sin(a_i) / (a_i - sin a_i cos a_i) (cos(a_i x / a) - cos a_i)
                  exp(-a_i^2 c t / a^2),          p0 = F B (1 + nu_u) / (3 a)
        u_y(y, t) = [-F (1 - nu) / (2 G a)
                     + F (1 - nu_u) / (G a) sum_i sin a_i cos a_i / (a_i - sin a_i cos a_i)
                       exp(-a_i^2 c t / a^2)] y
        u_x(x, t) = [F nu / (2 G a) - F nu_u / (G a) sum_i sin a_i cos a_i / (a_i - sin a_i cos a_i)
                     exp(..)] x + (F / G) sum_i cos a_i / (a_i - sin a_i cos a_i) sin(a_i x / a) exp(..)
        sigma_yy(x, t) = -F / a - (2 F (nu_u - nu) / (a (1 - nu))) sum_i sin a_i / (a_i - sin a_i cos a_i)
                         cos(a_i x / a) exp(..) + (2 F / a) sum_i sin a_i cos a_i / (a_i - sin a_i cos a_i) exp(..)

    For alpha = 1 and incompressible constituents c = kappa M_c, the same c_v as Terzaghi.
"""

import math

import numpy as np

# --------------------------------------------------------------------------------------------
# elastic moduli
# --------------------------------------------------------------------------------------------


def lame(E, nu):
    """Lame constants (lambda, G) of Young's modulus E and Poisson's ratio nu."""
    return E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), E / (2.0 * (1.0 + nu))


def constrained_modulus(E, nu):
    """Oedometric (constrained) modulus M_c = lambda + 2 G = E (1 - nu) / ((1 + nu)(1 - 2 nu))."""
    lam, G = lame(E, nu)
    return lam + 2.0 * G


# --------------------------------------------------------------------------------------------
# Terzaghi
# --------------------------------------------------------------------------------------------


def _terzaghi_roots(n):
    """M_m = pi (2 m + 1) / 2, m = 0 .. n-1."""
    return 0.5 * np.pi * (2.0 * np.arange(n) + 1.0)


def terzaghi_initial_pressure(q, M_c, alpha=1.0, storage=0.0):
    """Undrained pressure p0 = alpha q / (alpha^2 + S M_c) right after the step load q (> 0)."""
    return alpha * q / (alpha * alpha + storage * M_c)


def terzaghi_cv(mobility, M_c, alpha=1.0, storage=0.0):
    """Consolidation coefficient c_v = (k/mu_w) M_c / (alpha^2 + S M_c) [m2/s]."""
    return mobility * M_c / (alpha * alpha + storage * M_c)


def terzaghi_settlement_limits(q, H, M_c, alpha=1.0, storage=0.0):
    """(immediate, final) top displacement (negative = downward): eps0 H and -q H / M_c."""
    p0 = terzaghi_initial_pressure(q, M_c, alpha, storage)
    return -storage * p0 / alpha * H, -q * H / M_c


def _mode_factors_exact(M, cv, H, t):
    return np.exp(-np.outer(M * M, np.atleast_1d(t) * cv / (H * H)).T)  # (nt, nm)


def _mode_factors_be(M, cv, H, step_times):
    """Backward-Euler amplification after each step: prod_i 1 / (1 + M^2 c_v dt_i / H^2)."""
    times = np.concatenate(([0.0], np.asarray(step_times, dtype=float)))
    dts = np.diff(times)
    if np.any(dts <= 0.0):
        raise ValueError("step times must be increasing and positive")
    lam = M * M * cv / (H * H)
    log_g = -np.log1p(np.outer(dts, lam))  # (nsteps, nm)
    return np.exp(np.cumsum(log_g, axis=0))


def terzaghi_pressure(z, t, q, H, M_c, mobility, alpha=1.0, storage=0.0, tol=1e-12):
    """Exact pressure p(z, t) [Pa]; z depth below the drained top (0 <= z <= H), t > 0.

    z and t may be arrays; returns an array of shape (len(t), len(z)) (squeezed for scalars).
    For T = c_v t / H^2 < 0.05 the image (erfc) series is used, which converges in a few terms;
    otherwise the Fourier series.  At t <= 0 (right after loading) returns p0 (except z = 0).
    """
    z = np.atleast_1d(np.asarray(z, dtype=float))
    ts = np.atleast_1d(np.asarray(t, dtype=float))
    p0 = terzaghi_initial_pressure(q, M_c, alpha, storage)
    cv = terzaghi_cv(mobility, M_c, alpha, storage)
    out = np.empty((ts.size, z.size))
    erfc = np.vectorize(math.erfc)
    for i, ti in enumerate(ts):
        T = cv * ti / (H * H)
        if T <= 0.0:
            out[i] = np.where(z == 0.0, 0.0, p0)
        elif T < 0.05:
            # images: p/p0 = 1 - sum_j (-1)^j [erfc((2jH + z)/(2 sqrt(c t))) + erfc((2(j+1)H - z)/..)]
            d = 2.0 * math.sqrt(cv * ti)
            acc = np.zeros_like(z)
            for j in range(0, 50):
                term = erfc((2 * j * H + z) / d) + erfc((2 * (j + 1) * H - z) / d)
                acc += (-1) ** j * term
                if np.max(np.abs(term)) < tol:
                    break
            out[i] = p0 * (1.0 - acc)
        else:
            n = int(math.sqrt(-math.log(tol) / T) / math.pi) + 2
            M = _terzaghi_roots(n)
            modes = (2.0 / M) * np.exp(-M * M * T)
            out[i] = p0 * np.sin(np.outer(z / H, M)) @ modes
    return out.squeeze() if (np.ndim(t) == 0 or np.ndim(z) == 0) else out


def terzaghi_degree(t, H, M_c, mobility, alpha=1.0, storage=0.0, tol=1e-12):
    """Average remaining pressure ratio U_p(t) = (1/(p0 H)) int p dz = sum 2/M_m^2 exp(-M_m^2 T)."""
    ts = np.atleast_1d(np.asarray(t, dtype=float))
    cv = terzaghi_cv(mobility, M_c, alpha, storage)
    out = np.empty(ts.size)
    for i, ti in enumerate(ts):
        T = cv * ti / (H * H)
        if T <= 0.0:
            out[i] = 1.0
            continue
        # tail bound: sum_{M > M_N} 2/M^2 e^{-M^2 T} < e^{-M_N^2 T} / (pi M_N ...) -> choose M_N^2 T > -ln tol
        n = int(math.sqrt(-math.log(tol) / T) / math.pi) + 2
        M = _terzaghi_roots(n)
        out[i] = np.sum(2.0 / (M * M) * np.exp(-M * M * T))
    return out if np.ndim(t) else out[0]


def terzaghi_settlement(t, q, H, M_c, mobility, alpha=1.0, storage=0.0):
    """Exact top displacement s(t) [m] (negative = downward), t > 0 (t <= 0: the undrained one)."""
    p0 = terzaghi_initial_pressure(q, M_c, alpha, storage)
    U = terzaghi_degree(t, H, M_c, mobility, alpha, storage)
    return -q * H / M_c + alpha * p0 * H / M_c * U


def _be_terms(nsteps, tau_min, tol):
    """Number of Fourier terms so that the backward-Euler series tail is below tol (relative).

    Mode m after n steps is bounded by (2/M)(M^2 tau)^-n, so the tail beyond M_N is below
    tau^-n / (n pi M_N^(2n)); tau = c_v dt_min / H^2.
    """
    n = max(nsteps, 1)
    MN = (1.0 / (n * math.pi * tol * tau_min ** n)) ** (1.0 / (2 * n))
    return int(MN / math.pi) + 2


def terzaghi_pressure_be(z, step_times, q, H, M_c, mobility, alpha=1.0, storage=0.0,
                         tol=1e-9, max_terms=400000):
    """Backward-Euler (in time), exact-in-space pressure after each step.

    step_times: the end times t_1 < t_2 < ... of the steps (t_0 = 0, the load is on from the
    first step).  Returns an array (len(step_times), len(z)).  After the first step the
    solution is the closed form p0 (1 - cosh((H - z)/L) / cosh(H/L)), L = sqrt(c_v dt_1), used
    directly (the series converges as 1/M^3 there); later steps use the series.
    """
    z = np.atleast_1d(np.asarray(z, dtype=float))
    step_times = np.atleast_1d(np.asarray(step_times, dtype=float))
    p0 = terzaghi_initial_pressure(q, M_c, alpha, storage)
    cv = terzaghi_cv(mobility, M_c, alpha, storage)
    dts = np.diff(np.concatenate(([0.0], step_times)))
    tau_min = cv * dts.min() / (H * H)
    out = np.empty((step_times.size, z.size))
    # first step, closed form (cosh ratio written with exponentials to avoid overflow)
    L = math.sqrt(cv * dts[0])
    r = (np.exp(-z / L) + np.exp(-(2.0 * H - z) / L)) / (1.0 + math.exp(-2.0 * H / L))
    out[0] = p0 * (1.0 - r)
    if step_times.size > 1:
        n_terms = min(_be_terms(2, tau_min, tol), max_terms)
        M = _terzaghi_roots(n_terms)
        G = _mode_factors_be(M, cv, H, step_times)  # (nsteps, nm)
        S = np.sin(np.outer(z / H, M))  # (nz, nm)
        out[1:] = p0 * (G[1:] * (2.0 / M)) @ S.T
    return out


def terzaghi_pressure_be_series(z, step_times, q, H, M_c, mobility, alpha=1.0, storage=0.0,
                                n_terms=20000):
    """Backward-Euler pressure by the plain series for every step (used to self-check)."""
    z = np.atleast_1d(np.asarray(z, dtype=float))
    p0 = terzaghi_initial_pressure(q, M_c, alpha, storage)
    cv = terzaghi_cv(mobility, M_c, alpha, storage)
    M = _terzaghi_roots(n_terms)
    G = _mode_factors_be(M, cv, H, step_times)
    return p0 * (G * (2.0 / M)) @ np.sin(np.outer(z / H, M)).T


def terzaghi_settlement_be(step_times, q, H, M_c, mobility, alpha=1.0, storage=0.0,
                           n_terms=200000):
    """Backward-Euler (in time) top displacement after each step [m] (negative = downward)."""
    p0 = terzaghi_initial_pressure(q, M_c, alpha, storage)
    cv = terzaghi_cv(mobility, M_c, alpha, storage)
    M = _terzaghi_roots(n_terms)
    G = _mode_factors_be(M, cv, H, step_times)
    U = G @ (2.0 / (M * M))
    # the tail beyond M_N (terms ~ 2/M^2 (M^2 tau)^-1 at worst) is < 2/(pi tau M_N^3 ... ) ~ 1e-13
    return -q * H / M_c + alpha * p0 * H / M_c * U


# --------------------------------------------------------------------------------------------
# Mandel
# --------------------------------------------------------------------------------------------


def mandel_roots(nu, nu_u=0.5, n=400):
    """First n positive roots of tan(x) = K x, K = (1 - nu)/(nu_u - nu) > 1.

    Root i (1-based) lies in ((i-1) pi, (i-1/2) pi); found by bisection on
    g(x) = sin x - K x cos x, which has no poles.
    """
    if not (nu < nu_u <= 0.5):
        raise ValueError("need nu < nu_u <= 0.5")
    K = (1.0 - nu) / (nu_u - nu)
    i = np.arange(1, n + 1, dtype=float)
    lo = (i - 1.0) * np.pi + 1e-12
    hi = (i - 0.5) * np.pi
    g = lambda x: np.sin(x) - K * x * np.cos(x)
    glo = g(lo)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        gm = g(mid)
        same = np.sign(gm) == np.sign(glo)
        lo = np.where(same, mid, lo)
        glo = np.where(same, gm, glo)
        hi = np.where(same, hi, mid)
        if np.max(hi - lo) < 1e-15 * np.max(hi):
            break
    return 0.5 * (lo + hi)


class Mandel:
    """Mandel's problem (plane strain); see the module docstring.

    Parameters: E, nu (drained skeleton), mobility k/mu_w, half width a, half height b, F
    (force per unit thickness on a quarter model, i.e. half of the plate force 2F), Skempton B
    and undrained Poisson ratio nu_u (defaults: alpha = 1, incompressible constituents).
    """

    def __init__(self, E, nu, mobility, a, b, F, B=1.0, nu_u=0.5, n_roots=400):
        self.E, self.nu, self.mobility, self.a, self.b, self.F = E, nu, mobility, a, b, F
        self.B, self.nu_u = B, nu_u
        self.G = E / (2.0 * (1.0 + nu))
        self.c = (2.0 * mobility * B * B * self.G * (1.0 - nu) * (1.0 + nu_u) ** 2
                  / (9.0 * (1.0 - nu_u) * (nu_u - nu)))
        self.roots = mandel_roots(nu, nu_u, n_roots)
        al = self.roots
        self._den = al - np.sin(al) * np.cos(al)
        self.p0 = F * B * (1.0 + nu_u) / (3.0 * a)

    def time_factor(self, t):
        """Dimensionless time c t / a^2."""
        return self.c * np.asarray(t, dtype=float) / self.a ** 2

    def _decay(self, t):
        t = np.atleast_1d(np.asarray(t, dtype=float))
        return np.exp(-np.outer(t * self.c / self.a ** 2, self.roots ** 2))  # (nt, nr)

    def pressure(self, x, t):
        """p(x, t) [Pa] for t > 0; array (len(t), len(x)).  t <= 0 gives the undrained p0."""
        x = np.atleast_1d(np.asarray(x, dtype=float))
        t = np.atleast_1d(np.asarray(t, dtype=float))
        al = self.roots
        w = np.sin(al) / self._den
        shape = np.cos(np.outer(x / self.a, al)) - np.cos(al)  # (nx, nr)
        out = 2.0 * self.p0 * (self._decay(t) * w) @ shape.T
        out[t <= 0.0, :] = self.p0
        return out

    def _sum_sc(self, t):
        al = self.roots
        return self._decay(t) @ (np.sin(al) * np.cos(al) / self._den)

    def uy(self, y, t):
        """Vertical displacement u_y(y, t) [m]; at y = b: the plate displacement (negative)."""
        t = np.atleast_1d(np.asarray(t, dtype=float))
        F, G, a = self.F, self.G, self.a
        s = self._sum_sc(t)
        s = np.where(t <= 0.0, self._sum_sc_zero(), s)
        coef = -F * (1.0 - self.nu) / (2.0 * G * a) + F * (1.0 - self.nu_u) / (G * a) * s
        return np.outer(coef, np.atleast_1d(y)).squeeze()

    def _sum_sc_zero(self):
        # the t = 0 value of sum sin cos / den, (nu_u - nu) / (2 (1 - nu_u)) (undrained limit)
        return (self.nu_u - self.nu) / (2.0 * (1.0 - self.nu_u))

    def plate_displacement(self, t):
        """u_y(b, t): the prescribed displacement of the top plate of the quarter model."""
        return self.uy(self.b, t)

    def ux(self, x, t):
        """Horizontal displacement u_x(x, t) [m], array (len(t), len(x))."""
        x = np.atleast_1d(np.asarray(x, dtype=float))
        t = np.atleast_1d(np.asarray(t, dtype=float))
        F, G, a = self.F, self.G, self.a
        al = self.roots
        s = self._sum_sc(t)
        lin = F * self.nu / (2.0 * G * a) - F * self.nu_u / (G * a) * s
        sine = (self._decay(t) * (np.cos(al) / self._den)) @ np.sin(np.outer(x / a, al)).T
        return np.outer(lin, x) + F / G * sine

    def sigma_yy(self, x, t):
        """Total vertical stress sigma_yy(x, t) [Pa] (tension positive)."""
        x = np.atleast_1d(np.asarray(x, dtype=float))
        t = np.atleast_1d(np.asarray(t, dtype=float))
        F, a, nu, nu_u = self.F, self.a, self.nu, self.nu_u
        al = self.roots
        D = self._decay(t)
        t1 = (D * (np.sin(al) / self._den)) @ np.cos(np.outer(x / a, al)).T
        t2 = D @ (np.sin(al) * np.cos(al) / self._den)
        return -F / a - 2.0 * F * (nu_u - nu) / (a * (1.0 - nu)) * t1 + 2.0 * F / a * t2[:, None]

    def undrained(self):
        """Undrained (t = 0+) state: dict p0, uy_top (at y = b), ux_side (at x = a)."""
        G = self.G
        return {"p0": self.p0,
                "uy_top": -self.F * (1.0 - self.nu_u) / (2.0 * G * self.a) * self.b,
                "ux_side": self.F * self.nu_u / (2.0 * G)}

    def drained(self):
        """Drained (t -> infinity) state: uy_top and ux_side."""
        G = self.G
        return {"uy_top": -self.F * (1.0 - self.nu) / (2.0 * G * self.a) * self.b,
                "ux_side": self.F * self.nu / (2.0 * G)}


# --------------------------------------------------------------------------------------------
# Terzaghi column crossed by a permeable joint
# --------------------------------------------------------------------------------------------


class JointColumn:
    """Terzaghi's column (alpha = 1, S = 0, step load q, drained top, impervious fixed base)
    crossed at depth d by a closed joint of finite transversal transmissivity (docs/physics.md section 5):
    the water crossing it per unit area is f = T1 (p_below - p3) = T2 (p3 - p_above), so the
    pressure jumps by p_below - p_above = R f, R = 1/T1 + 1/T2, with f = kappa dp/dz (z depth,
    upward flux) continuous across it.  In each layer dp/dt = c p_zz, c = kappa M_c.

    Modes (self-adjoint with the plain L2 weight, the jump terms cancel):
        phi(z) = sin(lam z)                                   z < d
               = cos(lam d) / sin(lam (H - d)) cos(lam (H - z))   z > d
        cos(lam H) = R kappa lam cos(lam d) sin(lam (H - d))   (R = 0: Terzaghi's lam H = pi (2m+1)/2)
    p(z, t) = sum a_m phi_m(z) exp(-lam_m^2 c t), a_m = q int phi / int phi^2, int phi = 1/lam.
    Settlement s = -q H / M_c + (1/M_c) int p dz - (q - p3) / K_N: the last term the joint's
    penalty closure (p'_N = q - p3, no initial stress), p3 = p_below - f / T1.
    Neglected: the storage of the closing gap, (1/K_N) dp3/dt per unit area against the
    layers' H / M_c, a relative 1e-5 for K_N = 1e12, H = 1, M_c = 1.2e7."""

    def __init__(self, q, H, d, M_c, mobility, R, K_N=np.inf, T1=np.inf, tol=1e-13):
        self.q, self.H, self.d, self.Mc, self.kappa, self.R = q, H, d, M_c, mobility, R
        self.K_N, self.T1, self.tol = K_N, T1, tol
        self.c = mobility * M_c
        self._lam = np.empty(0)

    def _g(self, lam):
        H, d = self.H, self.d
        return np.cos(lam * H) - self.R * self.kappa * lam * np.cos(lam * d) * np.sin(lam * (H - d))

    def roots(self, lam_max):
        """The eigenvalues lam below lam_max (cached), by sign changes of g on a grid of
        pi/(64 H) and bisection (g has no poles)."""
        if self._lam.size and self._lam_max >= lam_max:
            return self._lam[self._lam <= lam_max]
        step = np.pi / (64.0 * self.H)
        x = np.arange(step * 0.5, lam_max + step, step)
        gx = self._g(x)
        i = np.nonzero(np.sign(gx[:-1]) != np.sign(gx[1:]))[0]
        lo, hi = x[i], x[i + 1]
        glo = gx[i]
        for _ in range(100):
            mid = 0.5 * (lo + hi)
            gm = self._g(mid)
            same = np.sign(gm) == np.sign(glo)
            lo, glo, hi = np.where(same, mid, lo), np.where(same, gm, glo), np.where(same, hi, mid)
        self._lam, self._lam_max = 0.5 * (lo + hi), lam_max
        return self._lam

    def _modes(self, t):
        t = float(t)
        if t <= 0.0:
            raise ValueError("JointColumn: t > 0 needed")
        lam = self.roots(math.sqrt(-math.log(self.tol) / (self.c * t)) + 4.0 * np.pi / self.H)
        H, d = self.H, self.d
        A = np.cos(lam * d) / np.sin(lam * (H - d))
        norm = (d / 2 - np.sin(2 * lam * d) / (4 * lam)
                + A * A * ((H - d) / 2 + np.sin(2 * lam * (H - d)) / (4 * lam)))
        a = self.q / lam / norm
        return lam, A, a * np.exp(-lam * lam * self.c * t)

    def pressure(self, z, times, side="below"):
        """p(z, t) [Pa] for each t; at z = d the side "below" (deeper) or "above"."""
        out = []
        for t in np.atleast_1d(times):
            lam, A, w = self._modes(t)
            below = z > self.d or (z == self.d and side == "below")
            phi = A * np.cos(lam * (self.H - z)) if below else np.sin(lam * z)
            out.append(float(w @ phi))
        return np.array(out)

    def jump(self, times):
        """p_below - p_above at the joint [Pa]."""
        out = []
        for t in np.atleast_1d(times):
            lam, A, w = self._modes(t)
            out.append(float(w @ (A * np.cos(lam * (self.H - self.d)) - np.sin(lam * self.d))))
        return np.array(out)

    def flux(self, times):
        """Upward water flux through the joint per unit area, kappa dp/dz at d [m/s]."""
        out = []
        for t in np.atleast_1d(times):
            lam, A, w = self._modes(t)
            out.append(float(w @ (self.kappa * lam * np.cos(lam * self.d))))
        return np.array(out)

    def settlement(self, times):
        """Top displacement [m] (negative = down), penalty closure of the joint included."""
        out = []
        for t in np.atleast_1d(times):
            lam, A, w = self._modes(t)
            integral = float(np.sum(w / lam))
            p_below = float(w @ (A * np.cos(lam * (self.H - self.d))))
            f = float(w @ (self.kappa * lam * np.cos(lam * self.d)))
            p3 = p_below - f / self.T1
            closure = (self.q - p3) / self.K_N if np.isfinite(self.K_N) else 0.0
            out.append(-self.q * self.H / self.Mc + integral / self.Mc - closure)
        return np.array(out)


def _selfcheck_joint(failures):
    q, H, Mc, kappa = 1e4, 1.0, constrained_modulus(1e7, 0.25), 1e-9
    cv = kappa * Mc
    # R -> 0: Terzaghi
    col = JointColumn(q, H, 0.5, Mc, kappa, 1e-6)
    zz = np.array([0.1, 0.25, 0.5, 0.75, 1.0])
    t = 0.1 * H * H / cv
    pj = np.array([col.pressure(z, t)[0] for z in zz])
    pt = terzaghi_pressure(zz, t, q, H, Mc, kappa)
    _check(np.max(np.abs(pj - pt)) < 1e-5 * q, "joint column with R -> 0 is Terzaghi", failures)
    # R = 1e9 (R kappa = 1 m): the PDE, flux continuity, the jump condition, mass balance
    R = 1e9
    col = JointColumn(q, H, 0.5, Mc, kappa, R)
    t, dt, dz = 0.05 * H * H / cv, 1e-5 * H * H / cv, 1e-4
    for z in (0.2, 0.8):
        p = lambda zv, tv: col.pressure(zv, tv)[0]
        res = (p(z, t + dt) - p(z, t - dt)) / (2 * dt) - cv * (p(z + dz, t) - 2 * p(z, t) + p(z - dz, t)) / dz ** 2
        _check(abs(res) < 1e-4 * q * cv / H ** 2, f"joint column: dp/dt = c p_zz at z = {z}", failures)
    p = lambda zv, side="below": col.pressure(zv, t, side)[0]
    fa = kappa * (3 * p(0.5, "above") - 4 * p(0.5 - dz) + p(0.5 - 2 * dz)) / (2 * dz)
    fb = kappa * (-3 * p(0.5, "below") + 4 * p(0.5 + dz) - p(0.5 + 2 * dz)) / (2 * dz)
    f = col.flux(t)[0]
    _check(abs(fa - f) < 1e-6 * abs(f) and abs(fb - f) < 1e-6 * abs(f),
           "joint column: flux continuous across the joint", failures)
    _check(abs(col.jump(t)[0] - R * f) < 1e-9 * q, "joint column: jump = R f", failures)
    _check(abs(p(0.0)) < 1e-9 * q, "joint column: p = 0 at the drained top", failures)
    # mass balance: d/dt int p dz = -c p_z(0), so ds/dt = -kappa p_z(0) (without closure)
    s = JointColumn(q, H, 0.5, Mc, kappa, R).settlement([t - dt, t + dt])
    top_flux = kappa * (-3 * p(0.0) + 4 * p(dz) - p(2 * dz)) / (2 * dz)
    _check(abs((s[1] - s[0]) / (2 * dt) + top_flux) < 1e-5 * abs(top_flux),
           "joint column: settlement rate = water out of the top", failures)
    p_early = np.array([col.pressure(z, 1e-6 * H * H / cv)[0] for z in (0.3, 0.7, 1.0)])
    _check(np.max(np.abs(p_early - q)) < 1e-3 * q, "joint column: p(z, 0+) = q", failures)
    _check(abs(col.settlement(1e3 * H * H / cv)[0] + q * H / Mc) < 1e-9 * q * H / Mc,
           "joint column: final settlement q H / M_c", failures)


# --------------------------------------------------------------------------------------------
# self-check
# --------------------------------------------------------------------------------------------


def _check(cond, msg, failures):
    print(("ok    " if cond else "FAIL  ") + msg)
    if not cond:
        failures.append(msg)


def _selfcheck():
    failures = []
    # ---- Terzaghi, alpha = 1, S = 0
    E, nu, k, H, q = 1e7, 0.25, 1e-12, 1.0, 1e4
    Mc = constrained_modulus(E, nu)
    kappa = k / 1e-3
    cv = terzaghi_cv(kappa, Mc)
    z = np.linspace(0.0, H, 41)
    # series and erfc forms agree around the switch T = 0.05
    T = np.array([0.049999, 0.050001])
    pA = terzaghi_pressure(z, T * H * H / cv, q, H, Mc, kappa)
    _check(np.max(np.abs(pA[0] - pA[1])) < 1e-4 * q, "Terzaghi erfc/Fourier forms agree at T=0.05",
           failures)
    # the Fourier form directly at T = 0.04 against the image form
    n = 4000
    M = _terzaghi_roots(n)
    t04 = 0.04 * H * H / cv
    pF = q * np.sin(np.outer(z / H, M)) @ (2.0 / M * np.exp(-M * M * 0.04))
    pI = terzaghi_pressure(z, t04, q, H, Mc, kappa)
    _check(np.max(np.abs(pF - pI)) < 1e-9 * q, "Terzaghi Fourier vs image series at T=0.04", failures)
    # early time: p -> q away from the top, p(0) = 0, monotone in z
    pe = terzaghi_pressure(z, 1e-6 * H * H / cv, q, H, Mc, kappa)
    _check(abs(pe[0]) < 1e-12 and abs(pe[-1] - q) < 1e-9 * q and np.all(np.diff(pe) >= -1e-9),
           "Terzaghi early time: p(0)=0, p->q, monotone", failures)
    # settlement limits and the integral of p (trapezoid on a fine grid)
    zf = np.linspace(0.0, H, 20001)
    for Tv in (0.01, 0.1, 0.5, 2.0):
        t = Tv * H * H / cv
        p = terzaghi_pressure(zf, t, q, H, Mc, kappa)
        integ = np.trapz(p, zf)
        s = terzaghi_settlement(t, q, H, Mc, kappa)
        _check(abs((-q * H + integ) / Mc - s) < 1e-6 * q * H / Mc,
               f"Terzaghi settlement = (-qH + int p)/M_c at T={Tv}", failures)
    s0, sinf = terzaghi_settlement_limits(q, H, Mc)
    _check(abs(terzaghi_settlement(1e-12, q, H, Mc, kappa) - s0) < 1e-4 * abs(sinf)
           and abs(terzaghi_settlement(1e6, q, H, Mc, kappa) - sinf) < 1e-12,
           "Terzaghi settlement limits 0 and -qH/M_c", failures)
    # classical value: U = 1 - U_p = 0.5 at T_v = 0.197
    U = 1.0 - terzaghi_degree(0.1967 * H * H / cv, H, Mc, kappa)
    _check(abs(U - 0.5) < 1e-3, f"Terzaghi degree of consolidation 0.5 at T_v=0.197 (got {U:.4f})",
           failures)
    # ---- general alpha and storage: undrained p0, limits, and PDE residual by finite differences
    alpha, S = 0.8, 2e-8
    p0 = terzaghi_initial_pressure(q, Mc, alpha, S)
    eps0 = -S * p0 / alpha
    _check(abs(alpha * eps0 + S * p0) < 1e-20 and abs(Mc * eps0 - alpha * p0 + q) < 1e-9 * q,
           "Terzaghi general alpha, 1/M: undrained p0 satisfies both balances", failures)
    cva = terzaghi_cv(kappa, Mc, alpha, S)
    t, dt = 0.05 * H * H / cva, 1e-5 * H * H / cva
    zz = np.linspace(0.1, 0.9, 9)
    dz = 1e-4
    pt = (terzaghi_pressure(zz, t + dt, q, H, Mc, kappa, alpha, S)
          - terzaghi_pressure(zz, t - dt, q, H, Mc, kappa, alpha, S)) / (2 * dt)
    pzz = (terzaghi_pressure(zz + dz, t, q, H, Mc, kappa, alpha, S)
           - 2 * terzaghi_pressure(zz, t, q, H, Mc, kappa, alpha, S)
           + terzaghi_pressure(zz - dz, t, q, H, Mc, kappa, alpha, S)) / dz ** 2
    # (alpha^2/M_c + S) dp/dt = kappa p_zz
    res = (alpha ** 2 / Mc + S) * pt - kappa * pzz
    _check(np.max(np.abs(res)) < 1e-4 * np.max(np.abs(kappa * pzz)),
           "Terzaghi general alpha, 1/M: diffusion equation residual", failures)
    sa = terzaghi_settlement(np.array([1e-12, 1e9]), q, H, Mc, kappa, alpha, S)
    s0a, sinfa = terzaghi_settlement_limits(q, H, Mc, alpha, S)
    _check(abs(sa[0] - s0a) < 1e-4 * abs(sinfa) and abs(sa[1] - sinfa) < 1e-12 * abs(sinfa),
           "Terzaghi general alpha, 1/M: settlement limits", failures)
    # ---- backward Euler
    dt = 1e-3 * H * H / cv
    times = dt * np.arange(1, 6)
    pb = terzaghi_pressure_be(z, times, q, H, Mc, kappa)
    pbs = terzaghi_pressure_be_series(z, times, q, H, Mc, kappa, n_terms=200000)
    _check(np.max(np.abs(pb - pbs)) < 2e-5 * q,
           f"BE closed form (step 1) and series agree ({np.max(np.abs(pb - pbs)) / q:.1e} q)",
           failures)
    # BE step 1 solves (I - c dt d2/dz2) p1 = p0: check by finite differences
    zz = np.linspace(0.05, 0.95, 19)
    dz = 1e-5
    f = lambda zv: terzaghi_pressure_be(zv, times[:1], q, H, Mc, kappa)[0]
    res = f(zz) - cv * dt * (f(zz + dz) - 2 * f(zz) + f(zz - dz)) / dz ** 2 - q
    _check(np.max(np.abs(res)) < 1e-4 * q, "BE step 1 satisfies (I - c dt D2) p1 = q", failures)
    # BE step 2 from step 1 (finite differences)
    g = lambda zv: terzaghi_pressure_be(zv, times[:2], q, H, Mc, kappa)[1]
    res = g(zz) - cv * dt * (g(zz + dz) - 2 * g(zz) + g(zz - dz)) / dz ** 2 - f(zz)
    _check(np.max(np.abs(res)) < 1e-4 * q, "BE step 2 satisfies (I - c dt D2) p2 = p1", failures)
    # BE tends to the exact solution as dt -> 0 (first order)
    tend = 0.05 * H * H / cv
    errs = []
    for nst in (10, 20, 40):
        tt = tend / nst * np.arange(1, nst + 1)
        errs.append(np.max(np.abs(terzaghi_pressure_be(z, tt, q, H, Mc, kappa)[-1]
                                  - terzaghi_pressure(z, tend, q, H, Mc, kappa))))
    rate = math.log2(errs[1] / errs[2])
    _check(0.9 < rate < 1.1, f"BE converges at first order in time (rate {rate:.2f})", failures)
    sb = terzaghi_settlement_be(times, q, H, Mc, kappa)
    sbi = np.array([(-q * H + np.trapz(terzaghi_pressure_be(zf, times, q, H, Mc, kappa)[i], zf)) / Mc
                    for i in range(len(times))])
    _check(np.max(np.abs(sb - sbi)) < 1e-6 * q * H / Mc, "BE settlement = (-qH + int p)/M_c",
           failures)
    # ---- Mandel, incompressible (nu_u = 0.5, B = 1)
    E, nu, k, a, b, F = 1e7, 0.0, 1e-12, 1.0, 1.0, 1e4
    m = Mandel(E, nu, k / 1e-3, a, b, F)
    K = (1 - nu) / (0.5 - nu)
    al = m.roots
    _check(np.max(np.abs(np.tan(al[:50]) - K * al[:50]) / (K * al[:50])) < 1e-8,
           f"Mandel roots (first {al[0]:.6f}, {al[1]:.6f})", failures)
    _check(abs(m.c - k / 1e-3 * constrained_modulus(E, nu)) < 1e-12 * m.c,
           "Mandel c = kappa M_c for incompressible constituents", failures)
    x = np.linspace(0.0, a, 11)
    mb = Mandel(E, nu, k / 1e-3, a, b, F, n_roots=200000)
    p_early = mb.pressure(x[:-1], 1e-9 * a * a / m.c)[0]
    _check(np.max(np.abs(p_early - m.p0)) < 2e-3 * m.p0,
           f"Mandel p(x, 0+) = F B (1+nu_u)/(3a) = {m.p0:.1f} uniform", failures)
    tt = np.array([1e-3, 0.01, 0.03, 0.05, 0.1, 0.2, 0.5, 1.0, 3.0]) * a * a / m.c
    pc = m.pressure(0.0, tt)[:, 0]
    _check(pc.max() > 1.05 * m.p0, f"Mandel-Cryer: centre p peaks at {pc.max() / m.p0:.3f} p0",
           failures)
    _check(m.pressure(0.0, 10.0 * a * a / m.c)[0, 0] < 1e-3 * m.p0, "Mandel: p -> 0", failures)
    sig = m.sigma_yy(np.linspace(0, a, 4001), tt)
    force = np.trapz(sig, np.linspace(0, a, 4001), axis=1)
    _check(np.max(np.abs(force + F)) < 1e-5 * F, "Mandel: int sigma_yy dx = -F at all times", failures)
    u0, ud = m.undrained(), m.drained()
    _check(abs(mb.plate_displacement(1e-9 * a * a / m.c) - u0["uy_top"]) < 1e-4 * abs(u0["uy_top"])  # O(sqrt(ct)/a)
           and abs(m.plate_displacement(0.0) - u0["uy_top"]) < 1e-12 * abs(u0["uy_top"])
           and abs(m.plate_displacement(50.0 * a * a / m.c) - ud["uy_top"]) < 1e-12 * abs(ud["uy_top"]),
           "Mandel plate displacement: undrained and drained limits", failures)
    _check(abs(mb.ux(a, 1e-9 * a * a / m.c)[0, 0] - u0["ux_side"]) < 1e-4 * u0["ux_side"]
           and abs(m.ux(a, 50.0 * a * a / m.c)[0, 0] - ud["ux_side"]) < 1e-9 * u0["ux_side"],
           "Mandel u_x(a): undrained and drained limits", failures)
    # mass balance (incompressible): d/dt(div u) = kappa p_xx at a few points (finite differences)
    t0 = 0.05 * a * a / m.c
    dt_, dx = 1e-6 * a * a / m.c, 1e-4
    xs = np.array([0.1, 0.3, 0.6, 0.9])

    def divu(tv):
        dux = (m.ux(xs + dx, tv) - m.ux(xs - dx, tv))[0] / (2 * dx)
        return dux + m.uy(1.0, tv) / 1.0

    lhs = (divu(t0 + dt_) - divu(t0 - dt_)) / (2 * dt_)
    pxx = (m.pressure(xs + dx, t0) - 2 * m.pressure(xs, t0) + m.pressure(xs - dx, t0))[0] / dx ** 2
    _check(np.max(np.abs(lhs - m.mobility * pxx)) < 1e-4 * np.max(np.abs(m.mobility * pxx)),
           "Mandel: fluid mass balance d(div u)/dt = kappa p_xx", failures)
    # general nu_u < 0.5 (compressible constituents): t=0 uniform pressure and sums
    mg = Mandel(E, 0.2, k / 1e-3, a, b, F, B=0.8, nu_u=0.4, n_roots=200000)
    pg = mg.pressure(x[:-1], 1e-9)[0]
    _check(np.max(np.abs(pg - mg.p0)) < 2e-3 * mg.p0, "Mandel general B, nu_u: p(x,0+) = p0",
           failures)
    _check(abs(mg._sum_sc(1e-12)[0] - mg._sum_sc_zero()) < 1e-4,
           "Mandel general: sum sin cos/den at t=0 = (nu_u-nu)/(2(1-nu_u))", failures)
    print("Mandel centre pressure p/p0 at c t/a^2 =", np.round(m.time_factor(tt), 3), ":",
          np.round(pc / m.p0, 4))
    _selfcheck_joint(failures)
    if failures:
        print(f"{len(failures)} self-check(s) FAILED")
        raise SystemExit(1)
    print("all analytic self-checks passed")


if __name__ == "__main__":
    _selfcheck()
