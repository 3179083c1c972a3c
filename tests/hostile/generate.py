#!/usr/bin/env python3
"""Writes the generated members of the hostile corpus (gen_*.scad, data/*):
deep nesting, very long tokens and deterministic binary garbage.  The output
is committed; run this again only to change it (the seed is fixed, so the
bytes are the same every time)."""
import os
import random

HERE = os.path.dirname(os.path.abspath(__file__))
DEEP = 50000


def put(name, data):
    path = os.path.join(HERE, name)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def main():
    rng = random.Random(20261122)
    # nesting the parser and evaluator must refuse or survive, not overflow
    put("gen_deep_parens.scad", "x = " + "(" * DEEP + "1" + ")" * DEEP + ";\necho(x);\n")
    put("gen_deep_parens_open.scad", "x = " + "(" * DEEP + "1;\n")
    put("gen_deep_brackets.scad", "x = " + "[" * DEEP + "1" + "]" * DEEP + ";\necho(len(x));\n")
    put("gen_deep_brackets_open.scad", "[" * DEEP)
    put("gen_deep_braces.scad", "{" * DEEP + "cube();" + "}" * DEEP + "\n")
    put("gen_deep_braces_open.scad", "{" * DEEP + "cube();\n")
    put("gen_deep_unary.scad", "x = " + "-" * DEEP + "1;\necho(x);\ny = " + "!" * DEEP + "true;\n")
    put("gen_deep_ternary.scad", "x = " + "true ? " * (DEEP // 4) + "1" + " : 0" * (DEEP // 4) + ";\necho(x);\n")
    put("gen_deep_transforms.scad", "translate([1, 0, 0]) " * (DEEP // 5) + "cube();\n")
    put("gen_deep_modifiers.scad", "#%" * (DEEP // 2) + "cube();\n")
    put("gen_deep_if.scad", "if (true) " * (DEEP // 4) + "cube();\n")
    put("gen_deep_let.scad", "x = " + "let (a = 1) " * (DEEP // 4) + "a;\necho(x);\n")
    put("gen_deep_index.scad", "x = [1];\necho(x" + "[0]" * DEEP + ");\n")
    put("gen_deep_calls.scad", "function f(x) = x;\necho(" + "f(" * (DEEP // 2) + "1" + ")" * (DEEP // 2) + ");\n")
    put("gen_deep_comprehension.scad",
        "x = " + "[for (i = [0:1]) " * 2000 + "i" + "]" * 2000 + ";\necho(len(x));\n")
    put("gen_deep_functions.scad",
        "".join("function f%d(x) = f%d(x) + 1;\n" % (i, i + 1) for i in range(5000))
        + "function f5000(x) = x;\necho(f0(0));\n")
    put("gen_deep_modules.scad",
        "".join("module m%d() m%d() children();\n" % (i, i + 1) for i in range(5000))
        + "module m5000() children();\nm0() cube();\n")
    put("gen_long_binary.scad", "x = 1" + " + 1" * DEEP + ";\necho(x);\ny = 1" + " ^ 1" * 1000 + ";\n")
    put("gen_many_args.scad", "cube(" + "1, " * DEEP + "1);\necho(" + "a = 1, " * 1000 + "1);\n")
    put("gen_many_statements.scad", "cube();\n" * (DEEP // 5))
    put("gen_many_assignments.scad", "".join("v%d = %d;\n" % (i, i) for i in range(DEEP // 5)) + "echo(v9999);\n")
    # very long tokens
    put("gen_long_identifier.scad", "a" * 100000 + " = 1;\necho(" + "a" * 100000 + ");\n")
    put("gen_long_string.scad", 'echo(len("' + "x" * 200000 + '"));\n')
    put("gen_long_number.scad", "echo(" + "9" * 20000 + ", 0." + "0" * 20000 + "1, 1e" + "9" * 1000 + ");\n")
    put("gen_long_comment.scad", "/*" + "*" * 100000 + "/\ncube();\n//" + "/" * 100000 + "\n")
    # binary garbage: random bytes, random printable soup, NULs in the middle
    for i in range(1, 5):
        put("gen_garbage_%d.scad" % i, bytes(rng.randrange(256) for _ in range(4096 * i)))
    soup = "(){}[]<>;,.=+-*/%!?:#$\"\\ \n\tabcxyz0123456789e"
    for i in range(1, 4):
        put("gen_soup_%d.scad" % i, "".join(rng.choice(soup) for _ in range(8192)))
    put("gen_nul_bytes.scad", b"cube();\n\0\0\0sphere();\n\0echo(\"a\0b\");\n")
    put("gen_utf16.scad", "cube(5);\n".encode("utf-16"))
    # files the hostile imports read (not .scad: the script does not run them)
    put("data/garbage.stl", bytes(rng.randrange(256) for _ in range(2000)))
    put("data/garbage.off", "OFF\n3 1 0\n0 0 nan\ninf 1 0\n0 1\n3 0 1 7\n")
    put("data/huge_counts.off", "OFF\n2000000000 2000000000 0\n0 0 0\n")
    put("data/empty.obj", "")
    put("data/garbage.dat", "1 2 x\n# c\nnan inf -inf\n1e999 3 4\n")
    put("data/ragged.dat", "1 2 3\n4\n5 6 7 8 9\n\n")
    put("data/garbage.png", b"\x89PNG\r\n\x1a\n" + bytes(rng.randrange(256) for _ in range(500)))
    mesh_import_files(random.Random(20261202))


def zipped(entries):
    """A ZIP archive (bytes) of (name, data) entries, deflated, fixed dates."""
    import io
    import zipfile
    b = io.BytesIO()
    with zipfile.ZipFile(b, "w", zipfile.ZIP_DEFLATED) as z:
        for name, data in entries:
            z.writestr(zipfile.ZipInfo(name, (2024, 1, 1, 0, 0, 0)), data)
    return b.getvalue()


def amf(objects, head="", tail="</amf>\n"):
    """An AMF document: objects as (vertices, triangles) of raw strings."""
    s = '<?xml version="1.0"?>\n<amf unit="millimeter">\n' + head
    for verts, tris in objects:
        s += "<object><mesh><vertices>\n"
        for x, y, z in verts:
            s += "<vertex><coordinates><x>%s</x><y>%s</y><z>%s</z></coordinates></vertex>\n" % (
                x, y, z)
        s += "</vertices><volume>\n"
        for a, b, c in tris:
            s += "<triangle><v1>%s</v1><v2>%s</v2><v3>%s</v3></triangle>\n" % (a, b, c)
        s += "</volume></mesh></object>\n"
    return s + tail


def model_3mf(body):
    """A 3MF package around a 3D/3dmodel.model of the given text."""
    types = ('<?xml version="1.0" encoding="UTF-8"?>\n<Types xmlns="http://schemas.'
             'openxmlformats.org/package/2006/content-types"><Default Extension="rels" '
             'ContentType="application/vnd.openxmlformats-package.relationships+xml"/>'
             '<Default Extension="model" ContentType="application/vnd.ms-package.'
             '3dmanufacturing-3dmodel+xml"/></Types>\n')
    rels = ('<?xml version="1.0" encoding="UTF-8"?>\n<Relationships xmlns="http://schemas.'
            'openxmlformats.org/package/2006/relationships"><Relationship Target="/3D/'
            '3dmodel.model" Id="rel0" Type="http://schemas.microsoft.com/3dmanufacturing/'
            '2013/01/3dmodel"/></Relationships>\n')
    return zipped([("[Content_Types].xml", types), ("_rels/.rels", rels),
                   ("3D/3dmodel.model", body)])


def mesh_import_files(rng):
    """The AMF and 3MF files import_amf_3mf.scad reads."""
    tet_v = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
    tet_t = [(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)]
    put("data/garbage.amf", bytes(rng.randrange(256) for _ in range(2000)))
    put("data/empty.amf", "")
    put("data/not_a_number.amf", amf([([(0, "1e", 0)] + tet_v[1:], tet_t)]))
    put("data/index_out_of_range.amf", amf([(tet_v, [(0, 2, 7), (0, -1, 3)] + tet_t)]))
    put("data/index_overflow.amf", amf([(tet_v, [(0, 2, 99999999999)] + tet_t)]))
    put("data/nan_inf.amf", amf([([("nan", 0, 0), ("inf", 0, 0)] + tet_v[2:], tet_t)]))
    put("data/truncated.amf", amf([(tet_v, tet_t)] * 2)[:-200])
    put("data/second_object_broken.amf", amf([(tet_v, tet_t), (tet_v, [(0, 1, "x")])]))
    put("data/empty_element.amf", amf([(tet_v, tet_t)], head="<metadata type='x'/>\n"))
    put("data/no_triangles.amf", amf([(tet_v, [])]))
    put("data/entities.amf", '<?xml version="1.0"?>\n<!DOCTYPE amf [\n'
        '<!ENTITY a "0000000000">\n<!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;">\n'
        '<!ENTITY c "&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;">\n'
        '<!ENTITY d "&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;">\n'
        '<!ENTITY e SYSTEM "file:///etc/passwd">\n]>\n'
        + amf([([("&d;", "&e;", 0)] + tet_v[1:], tet_t)])[len('<?xml version="1.0"?>\n'):])
    put("data/deep.amf", "<amf>" + "<object>" * 5000 + "</object>" * 5000 + "</amf>\n")
    put("data/zip_two_entries.amf", zipped([("a.amf", amf([(tet_v, tet_t)])),
                                            ("b.amf", amf([(tet_v, tet_t)]))]))
    put("data/zip_garbage.amf", zipped([("zip_garbage.amf",
                                         bytes(rng.randrange(256) for _ in range(3000)))]))
    put("data/garbage.3mf", bytes(rng.randrange(256) for _ in range(2000)))
    put("data/empty.3mf", "")
    put("data/no_model.3mf", zipped([("x.txt", "nothing")]))
    put("data/index_out_of_range.3mf", model_3mf(
        '<?xml version="1.0"?>\n<model unit="millimeter" xmlns="http://schemas.microsoft.com/'
        '3dmanufacturing/core/2015/02"><resources><object id="1" type="model"><mesh>'
        '<vertices><vertex x="0" y="0" z="0"/><vertex x="1" y="0" z="0"/>'
        '<vertex x="0" y="1" z="0"/></vertices><triangles><triangle v1="0" v2="1" v3="9"/>'
        '</triangles></mesh></object></resources><build><item objectid="1"/></build>'
        '</model>\n'))
    put("data/truncated.3mf", model_3mf(
        '<?xml version="1.0"?>\n<model unit="millimeter" xmlns="http://schemas.microsoft.com/'
        '3dmanufacturing/core/2015/02"><resources><object id="1" type="model"><mesh>'
        '<vertices><vertex x="0" y="0" z="0"/><vertex x='))


if __name__ == "__main__":
    main()
