#!/usr/bin/env python3
"""A synthetic assembly for the scale-out runs: K translated copies of one structure.

    bench/make_assembly.py data/pdb/1f2n_assembly1.cif.gz --copies 8 -o assembly.cif.gz

The input is an mmCIF file (gzipped or not) with an atom_site loop, as the capsid in
data/pdb is. The copies sit on a cubic grid (2 x 2 x 2 for 8), each shifted by a whole
number of angstroms: the structure's extent along the axis plus --gap (default 20 A, more
than two atoms' reach at any probe molsurf's radius tables allow), so no two copies touch
and each copy's coordinates keep the input's decimals exactly. Copy k > 0 renames every chain
(label_asym_id and auth_asym_id) CHAIN_k and numbers its atoms on, so all chains stay
distinct. The output is mmCIF (gzipped for a .gz name): PDB cannot hold more than 99 999
atoms. Python 3's standard library only.
"""
import argparse
import gzip
import math
import re
import sys
from decimal import Decimal

# An mmCIF value: quoted ('...' or "...", closed by the quote before a blank) or bare.
TOKEN = re.compile(r"""'(?:[^']|'(?=\S))*'|"(?:[^"]|"(?=\S))*"|\S+""")


def open_text(path, mode):
    if path.endswith(".gz"):
        return gzip.open(path, mode + "t", encoding="utf-8", compresslevel=1) if mode == "w" else gzip.open(
            path, "rt", encoding="utf-8")
    return open(path, mode, encoding="utf-8")


def read_atom_site(path):
    """The lines before the atom_site loop, its column names and its rows (lists of tokens)."""
    header, columns, rows = [], [], []
    state = "header"  # header -> loop (after loop_) -> columns -> rows -> done
    pending_loop = None
    with open_text(path, "r") as f:
        for line in f:
            stripped = line.strip()
            if state == "header":
                if stripped == "loop_":
                    pending_loop = line
                    state = "loop"
                else:
                    header.append(line)
            elif state == "loop":
                if stripped.startswith("_atom_site."):
                    columns.append(stripped[len("_atom_site."):])
                    state = "columns"
                else:
                    header.extend([pending_loop, line])
                    state = "header"
            elif state == "columns":
                if stripped.startswith("_atom_site."):
                    columns.append(stripped[len("_atom_site."):])
                else:
                    state = "rows"
            if state == "rows":
                if not stripped or stripped.startswith("#") or stripped == "loop_" or stripped.startswith("_"):
                    state = "done"
                    continue
                tokens = TOKEN.findall(stripped)
                if len(tokens) != len(columns):
                    sys.exit(f"{path}: an atom_site row with {len(tokens)} values for {len(columns)} columns: {stripped[:60]}")
                rows.append(tokens)
    if not rows:
        sys.exit(f"{path}: no atom_site loop (give an mmCIF file)")
    for needed in ("Cartn_x", "Cartn_y", "Cartn_z"):
        if needed not in columns:
            sys.exit(f"{path}: the atom_site loop has no {needed}")
    return header, columns, rows


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("structure", help="an mmCIF file (.cif or .cif.gz) with an atom_site loop")
    parser.add_argument("--copies", type=int, default=8, help="copies of the structure (default 8)")
    parser.add_argument("--gap", type=float, default=20.0, help="angstroms between copies' boxes (default 20)")
    parser.add_argument("-o", "--output", required=True, help="the assembly, .cif or .cif.gz")
    args = parser.parse_args()
    if args.copies < 1:
        sys.exit("--copies: at least 1")
    if not re.search(r"\.(cif|mmcif)(\.gz)?$", args.output):
        sys.exit(f"{args.output}: give an mmCIF name (.cif or .cif.gz); PDB holds at most 99 999 atoms")

    header, columns, rows = read_atom_site(args.structure)
    axes = [columns.index(c) for c in ("Cartn_x", "Cartn_y", "Cartn_z")]
    chain_columns = [columns.index(c) for c in ("label_asym_id", "auth_asym_id") if c in columns]
    id_column = columns.index("id") if "id" in columns else None
    lows = [min(float(r[a]) for r in rows) for a in axes]
    highs = [max(float(r[a]) for r in rows) for a in axes]
    steps = [Decimal(math.ceil(h - l + args.gap)) for l, h in zip(lows, highs)]
    side = math.ceil(round(args.copies ** (1 / 3), 9))

    with open_text(args.output, "w") as out:
        out.writelines(header)
        out.write("# %d copies of %s on a %d x %d x %d grid (bench/make_assembly.py, gap %g A)\n#\n"
                  % (args.copies, args.structure.split("/")[-1], side, side, side, args.gap))
        out.write("loop_\n")
        out.writelines("_atom_site.%s\n" % c for c in columns)
        serial = 0
        for k in range(args.copies):
            cell = (k % side, (k // side) % side, k // (side * side))
            shift = [steps[i] * cell[i] for i in range(3)]
            for row in rows:
                values = list(row)
                for i, a in enumerate(axes):
                    values[a] = str(Decimal(row[a]) + shift[i])  # exact: the input's decimals kept
                if k > 0:
                    for c in chain_columns:
                        values[c] = "%s_%d" % (row[c], k)
                serial += 1
                if id_column is not None:
                    values[id_column] = str(serial)
                out.write(" ".join(values) + "\n")
        out.write("#\n")
    print(f"{args.output}: {serial} atoms, {args.copies} copies of {len(rows)}, shifts {[str(s) for s in steps]} A",
          file=sys.stderr)


if __name__ == "__main__":
    main()
