#!/usr/bin/env python3
"""BEM electrostatics on molsurf's solvent-excluded surface, end to end (docs/bem.md).

A consumer test under the ctest label `long`: molsurf's SES mesh is given to a boundary-element
solver of the Poisson (Laplace) two-dielectric problem, and the solvation energy it gives is
checked against
  (a) Born's analytic energy of one ion, -332.0637 q^2/(2R) (1/eps_in - 1/eps_out) kcal/mol;
  (b) APBS (Debian's apbs, mg-auto, srfm smol, srad 1.4) for crambin (1crn) charged by Debian's
      pdb2pqr (AMBER), at molsurf densities 4 and 8 (the first-order panels need 4 to 8 vertices
      per A^2 for a few percent; any list with --densities).

The solver is the induced (apparent) surface charge formulation, a second-kind boundary integral
equation (Zauhar & Morgan 1985; Juffer et al. 1991 for kappa = 0): with eps_in inside the
surface, eps_out outside, n outward and phi = sum_k q_k/(eps_in |x - r_k|) + int sigma/|x - y|,
the jump of eps dphi/dn gives

    sigma - lam K' sigma = lam E0,   lam = (eps_out - eps_in) / (2 pi (eps_in + eps_out)),
    K' sigma (x) = int sigma(y) d/dn_x 1/|x - y| dA_y,   E0 = d/dn_x sum_k q_k/(eps_in |x - r_k|),

discretised with one constant per triangle, collocated at centroids (K'_ii = 0 on a flat
triangle), solved by GMRES; K' is applied by a Barnes-Hut treecode (quadrupole, theta 0.5) with
a near-field correction by subdivided quadrature. The energy is 1/2 * 332.0637 * sum_k q_k
phi_reaction(r_k) kcal/mol. numpy, scipy and numba come from Debian (scripts/setup_bem.sh).

If bempp-cl (numba backend) can be imported (BEMPP_CL_PATH names a folder holding the bempp_cl
package, or it is installed), the Born case is also solved with bempp-cl's two-domain
formulation (P1 spaces, as in its solvation tutorial) as a cross-check.

Usage (ctest sets MOLSURF_CLI and MOLSURF_DATA_DIR):
  bem_solvation.py [--densities 4,8] [--eps-in 1] [--workdir DIR] [--no-apbs]
Exit 0: every check within tolerance; 1: a check failed; 77: a tool is missing (skip).
"""
import argparse
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
import warnings
from pathlib import Path

SKIP = 77
KCAL = 332.0637  # kcal/mol * A / e^2

# numba's on-disk cache goes to a temporary folder, not beside this file in the source tree.
os.environ.setdefault("NUMBA_CACHE_DIR", os.path.join(tempfile.gettempdir(), "molsurf_bem_numba_cache"))

try:
    import numpy as np
    import scipy.sparse as sp
    import scipy.sparse.linalg as sla
    from scipy.spatial import cKDTree
    import numba
    from numba import njit, prange
except ImportError as error:  # pragma: no cover - reported as a skip
    print(f"bem_solvation: skipped ({error}; Debian: python3-numpy python3-scipy python3-numba, "
          "scripts/setup_bem.sh)")
    sys.exit(SKIP)


warnings.filterwarnings("ignore", message="splu converted its input to CSC format")


# --------------------------------------------------------------------------------------------
# Mesh input: molsurf's .off (OFF, vertex count, face count, then "3 a b c").

def read_off(path):
    tokens = Path(path).read_text().split()
    if tokens[0] != "OFF":
        raise ValueError(f"{path}: not an OFF file")
    nv, nf = int(tokens[1]), int(tokens[2])
    start = 4
    points = np.array(tokens[start:start + 3 * nv], dtype=float).reshape(nv, 3)
    faces = np.array(tokens[start + 3 * nv:start + 3 * nv + 4 * nf], dtype=np.int64).reshape(nf, 4)
    if not np.all(faces[:, 0] == 3):
        raise ValueError(f"{path}: faces that are not triangles")
    return points, faces[:, 1:]


def panels(points, triangles):
    a, b, c = (points[triangles[:, k]] for k in range(3))
    cross = np.cross(b - a, c - a)
    twice_area = np.linalg.norm(cross, axis=1)
    if np.any(twice_area <= 0):
        raise ValueError(f"{int(np.sum(twice_area <= 0))} triangles of zero area")
    normals = cross / twice_area[:, None]
    centroids = (a + b + c) / 3
    diameters = np.max([np.linalg.norm(b - a, axis=1), np.linalg.norm(c - b, axis=1),
                        np.linalg.norm(a - c, axis=1)], axis=0)
    return a, b, c, centroids, normals, 0.5 * twice_area, diameters


# --------------------------------------------------------------------------------------------
# Quadrature over one flat triangle: its m*m congruent sub-triangles, each at its centroid.

@njit(cache=True, inline="always")
def _subtriangle_point(a, b, c, m, s, t, up):
    # sub-triangle (s, t) of the m-grid in barycentric steps; its centroid
    if up:
        u = (s + 1.0 / 3.0) / m
        v = (t + 1.0 / 3.0) / m
    else:
        u = (s + 2.0 / 3.0) / m
        v = (t + 2.0 / 3.0) / m
    w = 1.0 - u - v
    return (w * a[0] + u * b[0] + v * c[0], w * a[1] + u * b[1] + v * c[1], w * a[2] + u * b[2] + v * c[2])


@njit(cache=True)
def _triangle_integrals(x, nx, a, b, c, area, m):
    """(int 1/|x-y| dA, int d/dn_x 1/|x-y| dA) over triangle abc by m*m sub-triangles."""
    w = area / (m * m)
    single = 0.0
    adjoint = 0.0
    for s in range(m):
        for t in range(m - s):
            for up in (True, False):
                if not up and t >= m - s - 1:
                    continue
                p = _subtriangle_point(a, b, c, m, s, t, up)
                dx = x[0] - p[0]
                dy = x[1] - p[1]
                dz = x[2] - p[2]
                r2 = dx * dx + dy * dy + dz * dz
                r = math.sqrt(r2)
                single += w / r
                adjoint -= w * (dx * nx[0] + dy * nx[1] + dz * nx[2]) / (r2 * r)
    return single, adjoint


@njit(cache=True, parallel=True)
def _near_corrections(rows, cols, cen, nor, A, B, C, area, diam, ratio):
    """K'_ij by subdivided quadrature minus its centroid value, for the near pairs (i, j)."""
    out = np.zeros(rows.shape[0])
    for k in prange(rows.shape[0]):
        i = rows[k]
        j = cols[k]
        dx = cen[i, 0] - cen[j, 0]
        dy = cen[i, 1] - cen[j, 1]
        dz = cen[i, 2] - cen[j, 2]
        r = math.sqrt(dx * dx + dy * dy + dz * dz)
        centroid = -area[j] * (dx * nor[i, 0] + dy * nor[i, 1] + dz * nor[i, 2]) / (r * r * r)
        m = int(min(32.0, max(4.0, math.ceil(ratio * diam[j] / r))))
        _, exact = _triangle_integrals(cen[i], nor[i], A[j], B[j], C[j], area[j], m)
        out[k] = exact - centroid
    return out


# --------------------------------------------------------------------------------------------
# Barnes-Hut treecode for sum_j q_j grad_x 1/|x - y_j| at the centroids (quadrupole expansions).

class Octree:
    def __init__(self, points, leaf_size=48):
        self.order = np.arange(len(points))
        # Built breadth-first: a node is a contiguous range of self.order, split in octants.
        node_ranges = [(0, len(points))]
        children = [[]]
        head = 0
        pts = points
        while head < len(node_ranges):
            start, end = node_ranges[head]
            if end - start > leaf_size:
                idx = self.order[start:end]
                p = pts[idx]
                mid = 0.5 * (p.min(axis=0) + p.max(axis=0))
                code = ((p[:, 0] > mid[0]).astype(np.int64) | ((p[:, 1] > mid[1]).astype(np.int64) << 1)
                        | ((p[:, 2] > mid[2]).astype(np.int64) << 2))
                sort = np.argsort(code, kind="stable")
                self.order[start:end] = idx[sort]
                counts = np.bincount(code, minlength=8)
                offset = start
                kids = []
                if np.count_nonzero(counts) > 1:
                    for count in counts:
                        if count:
                            kids.append(len(node_ranges))
                            node_ranges.append((offset, offset + int(count)))
                            children.append([])
                            offset += int(count)
                children[head] = kids
            head += 1
        count = len(node_ranges)
        self.start = np.array([r[0] for r in node_ranges], dtype=np.int64)
        self.end = np.array([r[1] for r in node_ranges], dtype=np.int64)
        self.child_start = np.zeros(count + 1, dtype=np.int64)
        flat = []
        for k in range(count):
            self.child_start[k] = len(flat)
            flat.extend(children[k])
        self.child_start[count] = len(flat)
        self.children = np.array(flat, dtype=np.int64)
        sorted_points = points[self.order]
        self.center = np.empty((count, 3))
        self.radius = np.empty(count)
        for k in range(count):
            p = sorted_points[self.start[k]:self.end[k]]
            c = 0.5 * (p.min(axis=0) + p.max(axis=0))
            self.center[k] = c
            self.radius[k] = np.sqrt(((p - c) ** 2).sum(axis=1).max())


@njit(cache=True, parallel=True)
def _moments(start, end, center, pts, q):
    n = start.shape[0]
    mom = np.zeros((n, 10))  # Q0, D(3), Qxx Qyy Qzz Qxy Qxz Qyz (traceless, 3dd - d^2 I)
    for k in prange(n):
        for j in range(start[k], end[k]):
            dx = pts[j, 0] - center[k, 0]
            dy = pts[j, 1] - center[k, 1]
            dz = pts[j, 2] - center[k, 2]
            d2 = dx * dx + dy * dy + dz * dz
            w = q[j]
            mom[k, 0] += w
            mom[k, 1] += w * dx
            mom[k, 2] += w * dy
            mom[k, 3] += w * dz
            mom[k, 4] += w * (3 * dx * dx - d2)
            mom[k, 5] += w * (3 * dy * dy - d2)
            mom[k, 6] += w * (3 * dz * dz - d2)
            mom[k, 7] += w * 3 * dx * dy
            mom[k, 8] += w * 3 * dx * dz
            mom[k, 9] += w * 3 * dy * dz
    return mom


@njit(cache=True, parallel=True)
def _normal_field(targets, tnormals, tindex, pts, q, start, end, child_start, children, center,
                  radius, mom, theta):
    """n_i . sum_j q_j grad 1/|x_i - y_j| (the source with index tindex[i] left out)."""
    nt = targets.shape[0]
    out = np.zeros(nt)
    for i in prange(nt):
        x0 = targets[i, 0]
        x1 = targets[i, 1]
        x2 = targets[i, 2]
        gx = 0.0
        gy = 0.0
        gz = 0.0
        stack = np.empty(256, dtype=np.int64)
        top = 0
        stack[top] = 0
        top += 1
        while top > 0:
            top -= 1
            k = stack[top]
            rx = x0 - center[k, 0]
            ry = x1 - center[k, 1]
            rz = x2 - center[k, 2]
            r2 = rx * rx + ry * ry + rz * rz
            if radius[k] * radius[k] < theta * theta * r2:
                r = math.sqrt(r2)
                inv = 1.0 / r
                inv3 = inv * inv * inv
                inv5 = inv3 * inv * inv
                inv7 = inv5 * inv * inv
                q0 = mom[k, 0]
                dr = mom[k, 1] * rx + mom[k, 2] * ry + mom[k, 3] * rz
                qrx = mom[k, 4] * rx + mom[k, 7] * ry + mom[k, 8] * rz
                qry = mom[k, 7] * rx + mom[k, 5] * ry + mom[k, 9] * rz
                qrz = mom[k, 8] * rx + mom[k, 9] * ry + mom[k, 6] * rz
                rqr = rx * qrx + ry * qry + rz * qrz
                s = -q0 * inv3 - 3.0 * dr * inv5 - 2.5 * rqr * inv7
                gx += s * rx + mom[k, 1] * inv3 + qrx * inv5
                gy += s * ry + mom[k, 2] * inv3 + qry * inv5
                gz += s * rz + mom[k, 3] * inv3 + qrz * inv5
            elif child_start[k + 1] == child_start[k]:
                for j in range(start[k], end[k]):
                    if j == tindex[i]:
                        continue
                    dx = x0 - pts[j, 0]
                    dy = x1 - pts[j, 1]
                    dz = x2 - pts[j, 2]
                    d2 = dx * dx + dy * dy + dz * dz
                    f = -q[j] / (d2 * math.sqrt(d2))
                    gx += f * dx
                    gy += f * dy
                    gz += f * dz
            else:
                for c in range(child_start[k], child_start[k + 1]):
                    stack[top] = children[c]
                    top += 1
        out[i] = gx * tnormals[i, 0] + gy * tnormals[i, 1] + gz * tnormals[i, 2]
    return out


@njit(cache=True, parallel=True)
def _direct_normal_field(cen, nor, q):
    n = cen.shape[0]
    out = np.zeros(n)
    for i in prange(n):
        s = 0.0
        for j in range(n):
            if j == i:
                continue
            dx = cen[i, 0] - cen[j, 0]
            dy = cen[i, 1] - cen[j, 1]
            dz = cen[i, 2] - cen[j, 2]
            d2 = dx * dx + dy * dy + dz * dz
            s -= q[j] * (dx * nor[i, 0] + dy * nor[i, 1] + dz * nor[i, 2]) / (d2 * math.sqrt(d2))
        out[i] = s
    return out


@njit(cache=True, parallel=True)
def _charge_field(cen, nor, xq, q, eps_in):
    n = cen.shape[0]
    out = np.zeros(n)
    for i in prange(n):
        s = 0.0
        for k in range(xq.shape[0]):
            dx = cen[i, 0] - xq[k, 0]
            dy = cen[i, 1] - xq[k, 1]
            dz = cen[i, 2] - xq[k, 2]
            d2 = dx * dx + dy * dy + dz * dz
            s -= q[k] * (dx * nor[i, 0] + dy * nor[i, 1] + dz * nor[i, 2]) / (d2 * math.sqrt(d2))
        out[i] = s / eps_in
    return out


@njit(cache=True, parallel=True)
def _reaction_potential(xq, sigma, cen, nor, A, B, C, area, diam, ratio):
    nq = xq.shape[0]
    out = np.zeros(nq)
    for k in prange(nq):
        s = 0.0
        for j in range(cen.shape[0]):
            dx = xq[k, 0] - cen[j, 0]
            dy = xq[k, 1] - cen[j, 1]
            dz = xq[k, 2] - cen[j, 2]
            r = math.sqrt(dx * dx + dy * dy + dz * dz)
            if r < ratio * diam[j]:
                m = int(min(32.0, max(4.0, math.ceil(ratio * diam[j] / r))))
                single, _ = _triangle_integrals(xq[k], nor[j], A[j], B[j], C[j], area[j], m)
                s += sigma[j] * single
            else:
                s += sigma[j] * area[j] / r
        out[k] = s
    return out


def _gmres(operator, rhs, tol, counter):
    try:
        return sla.gmres(operator, rhs, rtol=tol, atol=0.0, restart=100, maxiter=20, callback=counter,
                         callback_type="pr_norm")
    except TypeError:  # scipy < 1.12 (Debian 12's 1.10): tol
        return sla.gmres(operator, rhs, tol=tol, atol=0.0, restart=100, maxiter=20, callback=counter,
                         callback_type="pr_norm")


def solvation_energy(points, triangles, xq, q, eps_in, eps_out, theta=0.5, near=2.0, tol=1e-6,
                     direct=False):
    """Solvation (reaction field) energy in kcal/mol and a dict of diagnostics."""
    t0 = time.perf_counter()
    A, B, C, cen, nor, area, diam = panels(points, triangles)
    n = len(area)
    # Near pairs: targets i within near * diam_j of the centroid of source j.
    tree = cKDTree(cen)
    lists = tree.query_ball_point(cen, near * diam, workers=1)
    lengths = np.fromiter((len(x) for x in lists), dtype=np.int64, count=n)
    cols = np.repeat(np.arange(n, dtype=np.int64), lengths)
    rows = np.fromiter((i for x in lists for i in x), dtype=np.int64, count=int(lengths.sum()))
    keep = rows != cols
    rows, cols = rows[keep], cols[keep]
    corr = _near_corrections(rows, cols, cen, nor, A, B, C, area, diam, 4.0 * near)
    correction = sp.csr_matrix((corr, (rows, cols)), shape=(n, n))
    lam = (eps_out - eps_in) / (2 * math.pi * (eps_in + eps_out))

    if direct:
        def apply_kp(sigma):
            return _direct_normal_field(cen, nor, sigma * area) + correction @ sigma
    else:
        octree = Octree(cen)
        order = octree.order
        spts = np.ascontiguousarray(cen[order])
        rank = np.empty(n, dtype=np.int64)
        rank[order] = np.arange(n)

        def apply_kp(sigma):
            charges = (sigma * area)[order]
            mom = _moments(octree.start, octree.end, octree.center, spts, charges)
            field = _normal_field(cen, nor, rank, spts, charges, octree.start, octree.end,
                                  octree.child_start, octree.children, octree.center, octree.radius,
                                  mom, theta)
            return field + correction @ sigma

    rhs = lam * _charge_field(cen, nor, xq, q, eps_in)
    operator = sla.LinearOperator((n, n), matvec=lambda s: s - lam * apply_kp(np.asarray(s).ravel()),
                                  dtype=float)
    iterations = [0]

    def counter(_):
        iterations[0] += 1

    t1 = time.perf_counter()
    sigma, info = _gmres(operator, rhs, tol, counter)
    if info != 0:
        raise RuntimeError(f"GMRES did not converge (info {info})")
    phi = _reaction_potential(xq, sigma, cen, nor, A, B, C, area, diam, 4.0)
    energy = 0.5 * KCAL * float(np.dot(q, phi))
    t2 = time.perf_counter()
    return energy, {"faces": n, "near_pairs": len(rows), "iterations": iterations[0],
                    "induced_charge": float(np.dot(sigma, area)), "setup_s": t1 - t0,
                    "solve_s": t2 - t1}


# --------------------------------------------------------------------------------------------
# bempp-cl cross-check (optional): the two-domain formulation of bempp-cl's solvation tutorial.

def bempp_born(points, triangles, xq, q, eps_in, eps_out):
    path = os.environ.get("BEMPP_CL_PATH")
    if path:
        sys.path.insert(0, path)
    try:
        import bempp_cl.api as bempp
        from bempp_cl.api.operators.boundary import laplace, sparse
        from bempp_cl.api.operators.potential import laplace as potential
    except ImportError:
        return None
    grid = bempp.Grid(points.T.astype(float), triangles.T.astype(np.uint32))
    space = bempp.function_space(grid, "P", 1)
    identity = sparse.identity(space, space, space)
    slp = laplace.single_layer(space, space, space)
    dlp = laplace.double_layer(space, space, space)
    blocked = bempp.BlockedOperator(2, 2)
    blocked[0, 0] = 0.5 * identity + dlp
    blocked[0, 1] = -slp
    blocked[1, 0] = 0.5 * identity - dlp
    blocked[1, 1] = (eps_in / eps_out) * slp
    xq_, q_ = np.ascontiguousarray(xq), np.ascontiguousarray(q)

    @bempp.real_callable
    def coulomb(x, n, domain_index, result):
        s = 0.0
        for k in range(len(q_)):
            s += q_[k] / np.sqrt((x[0] - xq_[k, 0]) ** 2 + (x[1] - xq_[k, 1]) ** 2 + (x[2] - xq_[k, 2]) ** 2)
        result[0] = s / (4 * np.pi * eps_in)

    rhs = np.concatenate([bempp.GridFunction(space, fun=coulomb).coefficients, np.zeros(space.global_dof_count)])
    # bempp_cl.api.linalg.gmres passes rtol= (scipy >= 1.12): call scipy on the strong form here.
    solution, info = _gmres(blocked.strong_form(), rhs, 1e-6, lambda _: None)
    nd = space.global_dof_count
    u = bempp.GridFunction(space, coefficients=solution[:nd])
    dn = bempp.GridFunction(space, coefficients=solution[nd:])
    phi = potential.single_layer(space, xq.T) * dn - potential.double_layer(space, xq.T) * u
    return 2 * np.pi * KCAL * float(np.dot(q, phi.ravel()))


# --------------------------------------------------------------------------------------------
# APBS reference.

APBS_BLOCK = """elec name {name}
  mg-auto
  dime {dime} {dime} {dime}
  cglen {cglen:.1f} {cglen:.1f} {cglen:.1f}
  fglen {fglen:.1f} {fglen:.1f} {fglen:.1f}
  cgcent mol 1
  fgcent mol 1
  mol 1
  lpbe
  bcfl mdh
  pdie {pdie}
  sdie {sdie}
  chgm spl2
  srfm smol
  srad 1.4
  swin 0.3
  sdens 10.0
  temp 298.15
  calcenergy total
  calcforce no
end
"""


def apbs_solvation(pqr, xq, workdir, eps_in, eps_out, dime):
    extent = float((xq.max(axis=0) - xq.min(axis=0)).max())
    fglen = extent + 17.0
    cglen = 1.7 * fglen
    text = "read\n  mol pqr {}\nend\n".format(pqr)
    text += APBS_BLOCK.format(name="solvated", dime=dime, cglen=cglen, fglen=fglen, pdie=eps_in, sdie=eps_out)
    text += APBS_BLOCK.format(name="reference", dime=dime, cglen=cglen, fglen=fglen, pdie=eps_in, sdie=eps_in)
    text += "print elecEnergy solvated - reference end\nquit\n"
    path = Path(workdir) / f"apbs_{dime}.in"
    path.write_text(text)
    t = time.perf_counter()
    run = subprocess.run(["apbs", path.name], cwd=workdir, capture_output=True, text=True, timeout=3600)
    seconds = time.perf_counter() - t
    # The energy of the print statement (solvated - reference); APBS 3.4 may also print a
    # harmless "asc_getToken: Error" at the input's end.
    found = re.findall(r"Global net ELEC energy\s*=\s*(\S+)\s+kJ/mol", run.stdout)
    if not found:
        raise RuntimeError(f"apbs failed:\n{run.stdout[-2000:]}\n{run.stderr[-2000:]}")
    return float(found[-1]) / 4.184, fglen / (dime - 1), seconds


# --------------------------------------------------------------------------------------------

def read_pqr(path):
    xyz, charge, radius = [], [], []
    for line in Path(path).read_text().splitlines():
        if line.startswith(("ATOM", "HETATM")):
            fields = line[30:].split()
            xyz.append([float(v) for v in fields[:3]])
            charge.append(float(fields[3]))
            radius.append(float(fields[4]))
    return np.array(xyz), np.array(charge), np.array(radius)


def molsurf_mesh(cli, structure, out, density):
    t = time.perf_counter()
    # --hydrogens: molsurf drops hydrogens by default, even from a PQR; their charges would then
    # lie outside the surface (APBS counts their radii).
    subprocess.run([cli, str(structure), "--surface", "ses", "--hydrogens", "--density", str(density), "-o",
                    str(out), "-q"],
                   check=True, timeout=3600)
    return read_off(out), time.perf_counter() - t


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--densities", default="4,8", help="molsurf densities for 1crn (comma list)")
    parser.add_argument("--eps-in", type=float, default=1.0)
    parser.add_argument("--eps-out", type=float, default=80.0)
    parser.add_argument("--apbs-dime", type=int, default=161, help="APBS fine grid points per axis")
    parser.add_argument("--workdir", help="keep the files here (default: a temporary folder)")
    parser.add_argument("--no-apbs", action="store_true", help="1crn without the APBS comparison")
    parser.add_argument("--born-tolerance", type=float, default=0.02)
    parser.add_argument("--apbs-tolerance", type=float, default=0.05)
    args = parser.parse_args()

    cli = os.environ.get("MOLSURF_CLI") or shutil.which("molsurf")
    repo = Path(__file__).resolve().parents[2]
    data = Path(os.environ.get("MOLSURF_DATA_DIR", repo / "data"))
    if not cli or not Path(cli).is_file():
        cli = repo / "build" / "release" / "molsurf"
        if not cli.is_file():
            print("bem_solvation: skipped (no molsurf binary: set MOLSURF_CLI)")
            return SKIP
    missing = [tool for tool in ("pdb2pqr", "apbs") if not args.no_apbs and shutil.which(tool) is None]
    if missing:
        print(f"bem_solvation: skipped (missing {' '.join(missing)}; scripts/setup_bem.sh installs them)")
        return SKIP
    workdir = Path(args.workdir) if args.workdir else Path(tempfile.mkdtemp(prefix="molsurf_bem_"))
    workdir.mkdir(parents=True, exist_ok=True)
    failures = []
    print(f"numba {numba.__version__}, numpy {np.__version__}, {numba.config.NUMBA_NUM_THREADS} threads; "
          f"files in {workdir}", flush=True)

    # (a) Born ion: one atom, R = 2 A, q = +1, at the origin; SES of one atom = its sphere.
    radius, charge = 2.0, 1.0
    (workdir / "ion.xyzr").write_text(f"0 0 0 {radius}\n")
    xq, q = np.zeros((1, 3)), np.array([charge])
    print("\n(a) Born ion, R = 2 A, q = +1 e, eps_out = 80")
    print(f"{'eps_in':>6} {'density':>7} {'faces':>6} {'mesh R':>8} {'E (kcal/mol)':>13} {'Born':>10} "
          f"{'rel. err':>9} {'bempp-cl':>10} {'rel. err':>9} {'s':>6}")
    for eps_in in (1.0, 4.0):
        born = -KCAL * charge ** 2 / (2 * radius) * (1 / eps_in - 1 / args.eps_out)
        for density in (1, 4, 16):
            (points, triangles), _ = molsurf_mesh(cli, workdir / "ion.xyzr", workdir / f"ion_{density}.off", density)
            t = time.perf_counter()
            energy, info = solvation_energy(points, triangles, xq, q, eps_in, args.eps_out)
            seconds = time.perf_counter() - t
            bempp = bempp_born(points, triangles, xq, q, eps_in, args.eps_out) if density == 1 else None
            rel = (energy - born) / abs(born)
            text = f"{bempp:10.4f} {(bempp - born) / abs(born):9.2%}" if bempp is not None else f"{'-':>10} {'-':>9}"
            mesh_r = float(np.linalg.norm(points, axis=1).mean())
            print(f"{eps_in:6.0f} {density:7g} {info['faces']:6d} {mesh_r:8.4f} {energy:13.4f} {born:10.4f} "
                  f"{rel:9.2%} {text} {seconds:6.1f}", flush=True)
            if density == 16 and abs(rel) > args.born_tolerance:
                failures.append(f"Born eps_in {eps_in} density {density}: {rel:.2%}")

    # (b) Crambin: PQR from pdb2pqr (AMBER), SES meshes by molsurf, APBS mg-auto smol.
    pqr = workdir / "1crn.pqr"
    subprocess.run(["pdb2pqr", "--ff=AMBER", str(data / "pdb" / "1crn.pdb"), str(pqr)], check=True,
                   capture_output=True, timeout=600)
    xq, q, _ = read_pqr(pqr)
    print(f"\n(b) 1crn: {len(q)} atoms (pdb2pqr AMBER), net charge {q.sum():+.3f} e, eps_in {args.eps_in:g}, "
          f"eps_out {args.eps_out:g}, kappa 0")
    apbs = None
    if not args.no_apbs:
        apbs, spacing, apbs_s = apbs_solvation(pqr.name, xq, workdir, args.eps_in, args.eps_out, args.apbs_dime)
        print(f"APBS mg-auto (srfm smol, srad 1.4, fine grid {args.apbs_dime}^3, h = {spacing:.3f} A): "
              f"{apbs:.2f} kcal/mol in {apbs_s:.1f} s")
    print(f"{'density':>7} {'faces':>7} {'E (kcal/mol)':>13} {'APBS':>9} {'rel. diff':>9} {'GMRES it':>8} "
          f"{'molsurf s':>9} {'BEM s':>7}")
    for density in [float(d) for d in args.densities.split(",") if d]:
        (points, triangles), mesh_s = molsurf_mesh(cli, pqr, workdir / f"1crn_{density:g}.off", density)
        t = time.perf_counter()
        energy, info = solvation_energy(points, triangles, xq, q, args.eps_in, args.eps_out)
        seconds = time.perf_counter() - t
        rel = (energy - apbs) / abs(apbs) if apbs is not None else float("nan")
        print(f"{density:7g} {info['faces']:7d} {energy:13.2f} {apbs if apbs is not None else float('nan'):9.2f} "
              f"{rel:9.2%} {info['iterations']:8d} {mesh_s:9.1f} {seconds:7.1f}", flush=True)
        if apbs is not None and abs(rel) > args.apbs_tolerance:
            failures.append(f"1crn density {density:g}: {rel:.2%} from APBS")
    if not args.workdir:
        shutil.rmtree(workdir, ignore_errors=True)
    if failures:
        print("\nFAILED: " + "; ".join(failures))
        return 1
    print("\nall checks within tolerance")
    return 0


if __name__ == "__main__":
    sys.exit(main())
