#!/usr/bin/env python3
"""Packs the built `ig` with everything it loads, for a GPU machine that has
the NVIDIA driver but none of Debian's libraries (docs/results.md, "On a GPU").

    tools/bench/gpu_pack.py BUILD_DIR OUT_DIR [--keep REGEX]

OUT_DIR gets bin/ig and bin/shaders, lib/ (the shared-library closure of ig),
glibc/ (Debian's C library and loader, for a machine whose own is older),
proj/ and gdal/ (PROJ's and GDAL's data). The closure of GDAL and
OpenImageIO holds ~260 libraries (350 MB), mostly file-format drivers the
benchmark never opens (HDF5, Poppler, FFmpeg, OpenVDB, ...). Those named by
STUBBED are replaced by stubs: same SONAME, same version nodes, every symbol
the other libraries import from them defined, each function returning a
pointer to zeroed memory (a version query then reads an empty string). What
remains is 56 MB of libraries, 72 MB in all, 19 MB packed with xz. --keep REGEX keeps matching
libraries real (libxml2: Mesa's llvmpipe needs it when testing on this
machine)."""
import argparse
import os
import re
import shutil
import subprocess

STUBBED = (r"curl|odbc|xml2|blosc|armadillo|qhull|xerces|heif|poppler|netcdf|cfitsio|hdf5|"
           r"libpq|openjp2|kml|fyba|spatialite|mariadb|freexl|ogdi|geos|dfalt|mfhdf|opencv|"
           r"dcm|oflog|ofstd|avcodec|avformat|avutil|swscale|openvdb|raw_r|OpenColorIO|"
           r"freetype|crypto|gif")
# The C library and the GL dispatch libraries come from the machine (glvnd
# hands GL to the NVIDIA driver); the C library is also packed in glibc/.
SYSTEM = re.compile(r"^(libc|libm|libdl|libpthread|librt|ld-linux-x86-64|libGL|libEGL|libOpenGL|"
                    r"libGLX|libGLdispatch|libGLESv2)\.so")
GLIBC = ["libc.so.6", "libm.so.6", "libdl.so.2", "libpthread.so.0", "librt.so.1",
         "ld-linux-x86-64.so.2"]
LIB_DIRS = ("/lib/x86_64-linux-gnu", "/usr/lib/x86_64-linux-gnu", "/lib", "/usr/lib")


def readelf(*args):
    return subprocess.run(["readelf", *args], capture_output=True, text=True, check=True).stdout


def needed(path):
    return re.findall(r"\(NEEDED\).*\[(.+)\]", readelf("-dW", path))


def resolve(soname):
    for d in LIB_DIRS:
        path = os.path.join(d, soname)
        if os.path.exists(path):
            return path
    raise SystemExit(f"gpu_pack: {soname} is needed but not installed")


def dyn_symbols(path):
    """(name, version or None, default version?, type, bind, size, defined?) per dynamic symbol."""
    for line in readelf("--dyn-syms", "-W", path).splitlines():
        f = line.split()
        if len(f) < 8 or not f[0].rstrip(":").isdigit():
            continue
        _, _, size, typ, bind, _, ndx, name = f[:8]
        base, ver, default = name, None, True
        if "@@" in name:
            base, ver = name.split("@@")
        elif "@" in name:
            base, ver = name.split("@")
            default = False
        yield base, ver, default, typ, bind, int(size, 0), ndx not in ("UND", "ABS")


def imported_names(path):
    return {s[0] for s in dyn_symbols(path) if not s[6]}


def write_stub(real, soname, lib_dir, wanted, work_dir):
    """Assembles a library with real's SONAME and versions that defines the wanted symbols."""
    asm = [".section .bss", ".balign 64", "stub_zeros:", ".zero 4096", ".text"]
    versions = set()
    for n, (base, ver, default, typ, bind, size, defined) in enumerate(dyn_symbols(real)):
        if not defined or bind == "LOCAL" or base not in wanted:
            continue
        sym = f"stub_{n}"
        if typ in ("OBJECT", "TLS"):
            size = max(size, 1)
            section = '.section .tbss,"awT",@nobits' if typ == "TLS" else ".section .bss"
            kind = "tls_object" if typ == "TLS" else "object"
            asm += [section, ".balign 16", f".globl {sym}", f".type {sym},@{kind}",
                    f".size {sym},{size}", f"{sym}:", f".zero {size}", ".text"]
        else:
            asm += [f".globl {sym}", f".type {sym},@function", f"{sym}:",
                    "lea stub_zeros(%rip),%rax", "ret"]
        if bind == "WEAK":
            asm.append(f".weak {sym}")
        if ver:
            versions.add(ver)
            asm.append(f".symver {sym},{base}{'@@' if default else '@'}{ver}")
        else:
            asm += [f".globl {base}", f".set {base},{sym}"]
    source = os.path.join(work_dir, soname + ".s")
    with open(source, "w") as f:
        f.write("\n".join(asm) + "\n")
    args = ["gcc", "-shared", "-nostdlib", "-o", os.path.join(lib_dir, soname), source,
            f"-Wl,-soname,{soname}"]
    nodes = sorted(versions - {soname})
    if nodes:
        script = os.path.join(work_dir, soname + ".map")
        with open(script, "w") as f:
            f.write("".join(f"{v} {{ }};\n" for v in nodes))
        args.append(f"-Wl,--version-script={script}")
    subprocess.run(args, check=True)


def pack_libraries(binary, lib_dir, stubbed_re, work_dir):
    copied, stubbed, seen, todo = [], [], set(), list(needed(binary))
    while todo:
        soname = todo.pop()
        if soname in seen or SYSTEM.match(soname):
            continue
        seen.add(soname)
        real = resolve(soname)
        if stubbed_re.search(soname):
            stubbed.append((soname, real))
            continue
        shutil.copy2(real, os.path.join(lib_dir, soname), follow_symlinks=True)
        copied.append(soname)
        todo += needed(real)
    # Stubs define only what the packed objects import from them.
    wanted = imported_names(binary)
    for soname in copied:
        wanted |= imported_names(os.path.join(lib_dir, soname))
    for soname, real in stubbed:
        write_stub(real, soname, lib_dir, wanted, work_dir)
    return copied, [s for s, _ in stubbed]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("build_dir")
    ap.add_argument("out_dir")
    ap.add_argument("--keep", default="", help="regex of libraries kept real though STUBBED names them")
    a = ap.parse_args()
    stubbed = STUBBED
    if a.keep:
        stubbed = "|".join(p for p in STUBBED.split("|") if not re.search(a.keep, p))
    out = a.out_dir
    if os.path.exists(out):
        shutil.rmtree(out)
    for d in ("bin", "lib", "glibc", "proj", "stubs"):
        os.makedirs(os.path.join(out, d))
    binary = os.path.join(a.build_dir, "bin", "ig")
    shutil.copy2(binary, os.path.join(out, "bin", "ig"))
    shutil.copytree(os.path.join(a.build_dir, "bin", "shaders"), os.path.join(out, "bin", "shaders"))
    copied, stubs = pack_libraries(binary, os.path.join(out, "lib"), re.compile(stubbed),
                                   os.path.join(out, "stubs"))
    shutil.rmtree(os.path.join(out, "stubs"))
    for soname in GLIBC:
        shutil.copy2(resolve(soname), os.path.join(out, "glibc", soname), follow_symlinks=True)
    shutil.copy2("/usr/share/proj/proj.db", os.path.join(out, "proj", "proj.db"))
    shutil.copytree("/usr/share/gdal", os.path.join(out, "gdal"))
    print(f"gpu_pack: {out}: {len(copied)} libraries copied, {len(stubs)} stubbed "
          f"({', '.join(sorted(stubs))})")


if __name__ == "__main__":
    main()
