#!/usr/bin/env python3
"""The audit's output checked from outside: usage: audit_test.py AUDIT RECOMPUTE SCHEMA OUT_DIR

1. Mesh readers: the same closed mesh written as OFF, OBJ, PLY (ASCII, binary), STL (ASCII,
   binary) gives the same triangle count and the same scene results.
2. A small `incidence-audit all` run: audit.json validates against audit.schema.json; its
   numbers are consistent (fp + fn = wrong, rates, Pareto flags, scene test counts and adjacency
   recomputed here from the mesh file); every curve has exact 0 wrong, conservative 0 false no,
   aggressive 0 false yes.
3. A sample of stability points recomputed by audit_recompute with CGAL Epeck as the truth
   must equal the audit's counts, and the exact tier must agree with CGAL on all of them.
4. The HTML report exists and embeds one PNG per chart."""
import json
import math
import os
import struct
import subprocess
import sys

import jsonschema

AUDIT, RECOMPUTE, SCHEMA, OUT = sys.argv[1:5]
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAILED:", what)


def run(*args):
    r = subprocess.run(list(args), capture_output=True, text=True)
    if r.returncode != 0:
        print(r.stdout, r.stderr)
        sys.exit(f"{args[0]} exited with {r.returncode}")
    return r.stdout


# --- a closed test mesh: an octahedron subdivided twice, vertices at dyadic coordinates ----------
def octahedron(levels):
    verts = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
    faces = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
    for _ in range(levels):
        index = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in index:
                p, q = verts[a], verts[b]
                m = tuple((x + y) / 2 for x, y in zip(p, q))
                # push out a little, keeping values exact in binary32 (STL) and binary64
                s = 1.25 if sum(abs(c) for c in m) < 1 else 1.0
                verts.append(tuple(c * s for c in m))
                index[key] = len(verts) - 1
            return index[key]

        nf = []
        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            nf += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
        faces = nf
    return verts, faces


verts, faces = octahedron(2)
os.makedirs(OUT, exist_ok=True)


def normal(f):
    a, b, c = (verts[i] for i in f)
    u = [b[k] - a[k] for k in range(3)]
    v = [c[k] - a[k] for k in range(3)]
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def write_all(base):
    paths = {}
    p = base + ".off"
    with open(p, "w") as f:
        f.write(f"OFF\n# comment\n{len(verts)} {len(faces)} 0\n")
        f.writelines(f"{x!r} {y!r} {z!r}\n" for x, y, z in verts)
        f.writelines(f"3 {a} {b} {c}\n" for a, b, c in faces)
    paths["off"] = p
    p = base + ".obj"
    with open(p, "w") as f:
        f.writelines(f"v {x!r} {y!r} {z!r}\n" for x, y, z in verts)
        f.writelines(f"f {a + 1}/{a + 1} {b + 1} {c + 1}\n" for a, b, c in faces)
    paths["obj"] = p
    p = base + "_ascii.ply"
    with open(p, "w") as f:
        f.write(f"ply\nformat ascii 1.0\nelement vertex {len(verts)}\nproperty double x\nproperty double y\n"
                f"property double z\nelement face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n")
        f.writelines(f"{x!r} {y!r} {z!r}\n" for x, y, z in verts)
        f.writelines(f"3 {a} {b} {c}\n" for a, b, c in faces)
    paths["ply_ascii"] = p
    p = base + "_binary.ply"
    with open(p, "wb") as f:
        f.write((f"ply\nformat binary_little_endian 1.0\nelement vertex {len(verts)}\nproperty float x\n"
                 f"property float y\nproperty float z\nelement face {len(faces)}\n"
                 f"property list uchar int vertex_indices\nend_header\n").encode())
        for v in verts:
            f.write(struct.pack("<3f", *v))
        for t in faces:
            f.write(struct.pack("<B3i", 3, *t))
    paths["ply_binary"] = p
    p = base + "_ascii.stl"
    with open(p, "w") as f:
        f.write("solid test\n")
        for t in faces:
            f.write("facet normal %r %r %r\nouter loop\n" % normal(t))
            f.writelines("vertex %r %r %r\n" % verts[i] for i in t)
            f.write("endloop\nendfacet\n")
        f.write("endsolid test\n")
    paths["stl_ascii"] = p
    p = base + "_binary.stl"
    with open(p, "wb") as f:
        f.write(b"solid but binary".ljust(80, b" "))
        f.write(struct.pack("<I", len(faces)))
        for t in faces:
            f.write(struct.pack("<3f", *normal(t)))
            for i in t:
                f.write(struct.pack("<3f", *verts[i]))
            f.write(b"\0\0")
    paths["stl_binary"] = p
    return paths


paths = write_all(os.path.join(OUT, "octa"))

# 1. every reader gives the same scene
scenes = {}
for fmt, p in paths.items():
    d = os.path.join(OUT, "scene_" + fmt)
    run(AUDIT, "scene", p, "--rays", "3", "--pairs", "300", "--no-report", "--out", d)
    with open(os.path.join(d, "audit.json")) as f:
        scenes[fmt] = json.load(f)["scene"]
ref = scenes["off"]
check(ref["triangles"] == len(faces) and ref["vertices"] == len(verts), "OFF mesh size")
for fmt, s in scenes.items():
    check(s["triangles"] == ref["triangles"] and s["vertices"] == ref["vertices"], f"{fmt}: mesh size")
    for w, wr in zip(s["workloads"], ref["workloads"]):
        got = [(m["name"], m["wrong"], m["holes"], m["tests"]) for m in w["methods"]]
        want = [(m["name"], m["wrong"], m["holes"], m["tests"]) for m in wr["methods"]]
        check(got == want, f"{fmt}: workload {w['name']} differs from OFF")

# bad input is reported, not crashed on
bad = os.path.join(OUT, "bad.off")
with open(bad, "w") as f:
    f.write("OFF\n3 1 0\n0 0 0\n1 0 nan\n0 1 0\n3 0 1 2\n")
r = subprocess.run([AUDIT, "scene", bad, "--no-report", "--out", os.path.join(OUT, "bad")], capture_output=True, text=True)
check(r.returncode == 1 and "NaN" in r.stderr, "a NaN vertex is a clear error: " + r.stderr.strip())
r = subprocess.run([AUDIT, "scene", os.path.join(OUT, "missing.off"), "--no-report"], capture_output=True, text=True)
check(r.returncode == 1 and "cannot open" in r.stderr, "a missing file is a clear error")
r = subprocess.run([AUDIT, "stability", "--cases", "0"], capture_output=True, text=True)
check(r.returncode == 2 and "positive" in r.stderr, "a bad option is a clear error")

# 2. the full command, small
seed, cases = 4242, 6
out = os.path.join(OUT, "all")
run(AUDIT, "all", "--scene", paths["off"], "--cases", str(cases), "--seed", str(seed), "--tradeoff-cases", "400",
    "--reps", "2", "--rays", "4", "--pairs", "500", "--out", out)
with open(os.path.join(out, "audit.json")) as f:
    d = json.load(f)
with open(SCHEMA) as f:
    jsonschema.validate(d, json.load(f))

families = json.loads(run(RECOMPUTE, "--families"))
check([f["name"] for f in d["families"]] == families, "audit families = the library's catalog")
check([f["name"] for f in d["stability"]["families"]] == families, "stability covers every family")
check([f["name"] for f in d["tradeoff"]["families"]] == families, "tradeoff covers every family")
nset = len(d["stability"]["settings"])
for fam in d["stability"]["families"]:
    for m in fam["methods"]:
        for i in range(70):
            check(m["false_positive"][i] + m["false_negative"][i] == m["wrong"][i], f"{fam['name']} {m['name']} fp+fn")
            check(m["cases"][i] <= cases * nset, f"{fam['name']} {m['name']} case count")
        if m["kind"] != "peer":
            check(all(c == cases * nset for c in m["cases"]), f"{fam['name']} {m['name']} all cases counted")
        check(sum(s["wrong"] for s in m["by_setting"]) == sum(m["wrong"]), f"{fam['name']} {m['name']} by_setting")
        if m["name"] == "exact":
            check(sum(m["wrong"]) == 0, f"{fam['name']}: exact wrong")
        if m["name"] == "conservative":
            check(sum(m["false_negative"]) == 0, f"{fam['name']}: conservative false no")
        if m["name"] == "aggressive":
            check(sum(m["false_positive"]) == 0, f"{fam['name']}: aggressive false yes")
check(d["contract_violations"] == 0, "no contract violations")
for fam in d["tradeoff"]["families"]:
    ms = fam["methods"]
    for m in ms:
        dominated = any(q is not m and q["ns_near"] <= m["ns_near"] and q["error_rate_near"] <= m["error_rate_near"]
                        and (q["ns_near"] < m["ns_near"] or q["error_rate_near"] < m["error_rate_near"]) for q in ms)
        check(m["pareto"] == (not dominated), f"{fam['name']} {m['name']}: Pareto flag")
        if m["kind"] != "peer":
            check(math.isclose(m["error_rate_near"], m["wrong_near"] / fam["near_cases"]), f"{fam['name']} {m['name']} rate")
        if m["name"] == "exact":
            check(m["wrong_near"] == 0, f"{fam['name']}: exact wrong in tradeoff")

sc = d["scene"]
w = {x["name"]: x for x in sc["workloads"]}
check(w["camera_rays"]["tests"] == 16 * len(faces), "camera ray tests = rays x triangles")
check(w["scene_rays"]["tests"] == 16, "scene ray tests = rays")
check([m["name"] for m in w["scene_rays"]["methods"] if m["kind"] == "batch"] ==
      [t + " (batch)" for t in ["exact", "conservative", "aggressive", "approximate"]], "scene rays: a batch row per tier")
for m in w["scene_rays"]["methods"]:  # every ray of the grid aims at the mesh's box: the exact tier's yes/no, per ray
    if m["name"] in ("exact", "exact (batch)"):
        check(m["wrong"] == 0, f"scene rays: {m['name']} agrees with the exact scene")
check(sc["advice"]["scene_tier"] in [t["name"] for t in sc["tiers"]], "the advice names a scene tier")
check(w["edge_rays"]["tests"] == 3 * len(faces), "edge ray tests = 2 per edge of a closed mesh")
check(w["vertex_rays"]["tests"] == 3 * len(faces), "vertex ray tests = 3 per triangle")
around = {}
for i, t in enumerate(faces):
    for v in t:
        around.setdefault(v, set()).add(i)
adjacent = {(f, g) for s in around.values() for f in s for g in s if f < g}
check(w["adjacent_pairs"]["tests"] == len(adjacent), f"adjacent pairs {w['adjacent_pairs']['tests']} vs {len(adjacent)}")
for x in sc["workloads"]:
    ex = next(m for m in x["methods"] if m["name"] == "exact")
    check(ex["wrong"] == 0 and ex["holes"] == 0, f"scene {x['name']}: exact")
    for m in x["methods"]:
        check(m["false_positive"] + m["false_negative"] == m["wrong"], f"scene {x['name']} {m['name']} fp+fn")
adj = w["adjacent_pairs"]
check(all(m["false_positive"] == 0 for m in adj["methods"]), "adjacent pairs all touch: no false yes possible")
for t in sc["tiers"]:
    tot = sum(m["wrong"] for x in sc["workloads"] for m in x["methods"] if m["name"] == t["name"])
    check(t["wrong"] == tot, f"scene tier {t['name']} total")
best = sc["advice"]["tier"]
ok = [t for t in sc["tiers"] if t["wrong"] == 0]
check(best == min(ok, key=lambda t: t["ms"])["name"], "advice = cheapest tier without a mistake")

bv = sc["bounding_volumes"]
kinds = [r["kind"] for r in bv["rows"] if r["ours"]]
for k in ["aabb", "6-dop", "14-dop", "18-dop", "26-dop", "sphere (aabb)", "sphere (aabb, farthest)", "sphere (Ritter)",
          "sphere (Welzl, exact)"]:
    check(k in kinds, f"bounding volume {k} measured")
for r in bv["rows"]:
    if r["ours"]:
        check(r["contains_all"], f"{r['kind']} contains every vertex")
        check(r["volume_ratio"] >= 1.0 - 1e-9, f"{r['kind']} is not smaller than the convex hull")
rows = {r["kind"]: r for r in bv["rows"]}
check(abs(rows["aabb"]["volume_ratio"] - rows["6-dop"]["volume_ratio"]) <= 1e-9 * rows["aabb"]["volume_ratio"],
      "the 6-DOP is the AABB")
check(abs(rows["sphere (Welzl, exact)"]["volume_ratio"] - rows["CGAL min sphere"]["volume_ratio"]) <= 1e-9 *
      rows["CGAL min sphere"]["volume_ratio"], "Welzl's sphere = CGAL's minimum sphere")
check(rows["sphere (Welzl, exact)"]["volume_ratio"] <= rows["sphere (Ritter)"]["volume_ratio"], "Welzl <= Ritter")
# the octahedron's vertices are its hull: volume of the subdivided octahedron checked independently here
vol = 0.0
for a, b, c in faces:
    p, q, r = verts[a], verts[b], verts[c]
    vol += (p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0]) + p[2] * (q[0] * r[1] - q[1] * r[0])) / 6
check(math.isclose(abs(vol), bv["hull_volume"], rel_tol=1e-9), f"hull volume {bv['hull_volume']} vs {abs(vol)}")

# 3. recompute a sample with CGAL Epeck as the truth
sample_levels = [0, 25, 45, 60, 61, 62, 69]
st = {f["name"]: f for f in d["stability"]["families"]}
points = 0
for fi, name in enumerate(families):
    recs = [json.loads(line) for line in run(RECOMPUTE, str(seed), str(cases), str(fi), ",".join(map(str, sample_levels))).splitlines()]
    check(len(recs) == len(sample_levels), f"{name}: one record per sampled level")
    for level, rec in zip(sample_levels, recs):
        check(rec["level"] == level, f"{name}: records in the order of the levels")
        check(rec["skipped"] == 0, f"{name} level {level}: CGAL preconditions")
        for m in st[name]["methods"]:
            got = rec["methods"][m["name"]]
            want = [m["cases"][level], m["wrong"][level], m["false_positive"][level], m["false_negative"][level]]
            check(got == want, f"{name} level {level} {m['name']}: audit {want}, recomputed {got}")
            points += 1
        check(rec["methods"]["exact"][1] == 0, f"{name} level {level}: exact vs CGAL")
print(f"[cases] audit recomputed against CGAL Epeck: {points} method x level points, {len(failures)} failures")

# 4. the report
with open(os.path.join(out, "report.html")) as f:
    page = f.read()
n_img = page.count('src="data:image/png;base64,')
check(n_img == len(families) + 3, f"report images: {n_img}")
check("http://" not in page and "https://" not in page, "report needs no network")

print(f"[cases] audit output: {len(failures)} failures")
sys.exit(1 if failures else 0)
