#!/usr/bin/env python3
"""Per-residue, relative and per-chain SASA: molsurf's exact areas against FreeSASA's Lee-Richards.

Both tools write NACCESS's RSA layout (molsurf --format rsa, freesasa --format=rsa) with the same
atoms (no hetero atoms, no hydrogens, no water), ProtOr radii and a 1.4 A probe. FreeSASA runs at
2000 slices by default, where its own error is small. The table gives, per structure:
- residues: the largest and the 95th-percentile |difference| of each residue's area (A^2);
- relative: the 95th-percentile |difference| of relative SASA, both over Tien et al. 2013's
  theoretical maximum, and how many residues change side of RSA 0.25 (buried/exposed);
- chains: the largest |difference| of a chain's area, absolute (A^2) and relative.

    python3 bench/sasa_tables_vs_freesasa.py [--slices N] [STRUCTURE ...]

Default structures: data/pdb's 1crn, 1ubq, 2hhb, 4hhb, 3pqr and FreeSASA's own 1a0q (from the
freesasa package), which molsurf's tests never read.
"""
import argparse
import pathlib
import statistics
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
MOLSURF = ROOT / "build" / "release" / "molsurf"

# Tien et al. 2013, theoretical maxima (A^2): the reference --relative uses.
TIEN = {"ALA": 129, "ARG": 274, "ASN": 195, "ASP": 193, "CYS": 167, "GLN": 225, "GLU": 223, "GLY": 104,
        "HIS": 224, "ILE": 197, "LEU": 201, "LYS": 236, "MET": 224, "PHE": 240, "PRO": 159, "SER": 155,
        "THR": 172, "TRP": 285, "TYR": 263, "VAL": 174}


def parse_rsa(text):
    """{(chain, number+icode, name): area} and {chain: area} from an RSA text."""
    residues, chains = {}, {}
    for line in text.splitlines():
        if line.startswith("RES "):
            fields = line.split()
            if len(fields[2]) > 1:  # a number of four digits or more runs into the chain
                fields[2:3] = [fields[2][0], fields[2][1:]]
            residues[(fields[2], fields[3], fields[1])] = float(fields[4])
        elif line.startswith("CHAIN"):
            fields = line.split()
            chains[fields[2]] = float(fields[3])
    return residues, chains


def percentile(values, q):
    values = sorted(values)
    return values[min(len(values) - 1, int(round(q * (len(values) - 1))))] if values else float("nan")


def compare(path, slices):
    molsurf = subprocess.run([str(MOLSURF), str(path), "--no-hetatm", "--format", "rsa"], check=True,
                             capture_output=True, text=True).stdout
    cif = ["--cif"] if ".cif" in path.suffixes else []
    freesasa = subprocess.run(["freesasa", str(path), *cif, "--lee-richards", f"--resolution={slices}",
                               "--format=rsa", "--n-threads=2"], check=True, capture_output=True, text=True).stdout
    m_res, m_chain = parse_rsa(molsurf)
    f_res, f_chain = parse_rsa(freesasa)
    common = sorted(set(m_res) & set(f_res))
    diff = [abs(m_res[k] - f_res[k]) for k in common]
    rel = [(m_res[k] / TIEN[k[2]], f_res[k] / TIEN[k[2]]) for k in common if k[2] in TIEN]
    flips = sum((a >= 0.25) != (b >= 0.25) for a, b in rel)
    chain_diff = [(abs(m_chain[c] - f_chain[c]), abs(m_chain[c] - f_chain[c]) / f_chain[c])
                  for c in m_chain if c in f_chain and f_chain[c] > 0]
    return {
        "residues": len(common), "only_one": len(set(m_res) ^ set(f_res)),
        "res_max": max(diff), "res_p95": percentile(diff, 0.95),
        "rel_p95": percentile([abs(a - b) for a, b in rel], 0.95), "flips": flips, "rel_n": len(rel),
        "chain_max": max(d for d, _ in chain_diff), "chain_rel": max(r for _, r in chain_diff),
        "chains": len(chain_diff),
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("structures", nargs="*", type=pathlib.Path)
    parser.add_argument("--slices", type=int, default=2000)
    args = parser.parse_args()
    structures = args.structures or [ROOT / "data" / "pdb" / f for f in
                                     ("1crn.pdb", "1ubq.pdb", "2hhb.pdb", "4hhb.cif", "3pqr.cif")]
    if not args.structures and pathlib.Path("/usr/share/freesasa/test-data/1a0q.pdb").exists():
        structures.append(pathlib.Path("/usr/share/freesasa/test-data/1a0q.pdb"))
    print(f"molsurf (exact) against FreeSASA Lee-Richards at {args.slices} slices; ProtOr, probe 1.4 A")
    print("| structure | residues | residue max / p95 (A^2) | RSA p95 | flips at 0.25 | chains | chain max (A^2, rel.) |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for path in structures:
        r = compare(path, args.slices)
        print(f"| {path.name} | {r['residues']} | {r['res_max']:.2f} / {r['res_p95']:.2f} | {r['rel_p95']:.4f} | "
              f"{r['flips']} of {r['rel_n']} | {r['chains']} | {r['chain_max']:.2f} ({r['chain_rel']:.1e}) |")
        if r["only_one"]:
            print(f"  ({r['only_one']} residues in one table only)", file=sys.stderr)


if __name__ == "__main__":
    main()
