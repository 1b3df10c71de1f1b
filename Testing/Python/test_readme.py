"""Keep the README's code examples true.

Usage: pvpython test_readme.py <pvpython> <README.md> <OverlayStitchMesher.so> <source dir> <work dir>

1. Runs the pvpython example of "### 2. From pvpython or pvbatch" as it is
   written, from the source tree's root paths (the README's relative paths are
   made absolute: the plugin path to the built plugin, Testing/Data/ to the
   source tree's), in an empty work directory, and checks the mesh it writes.
2. Checks that every statement of the C++ example of "### 3. From C++" is a
   line of Testing/Consumer/app/main.cxx, the program the consumer tests build
   against the installed module, run and validate.
"""
import os
import re
import subprocess
import sys

README_PLUGIN = "build/lib/paraview-5.11/plugins/OverlayStitchMesher/OverlayStitchMesher.so"


def code_block(text, heading, language):
    """The first ```language block after the heading."""
    start = text.index(heading)
    match = re.compile(r"```" + language + r"\n(.*?)```", re.S).search(text, start)
    if not match:
        raise SystemExit("no %s block after %r" % (language, heading))
    return match.group(1)


def check_python(pvpython, readme, plugin, source, work):
    code = code_block(readme, "### 2. From pvpython or pvbatch", "python")
    if README_PLUGIN not in code or "Testing/Data/" not in code:
        print("FAILED: the pvpython example no longer names %s and Testing/Data/" % README_PLUGIN)
        return 1
    code = code.replace(README_PLUGIN, plugin)
    code = code.replace('"Testing/Data/', '"' + os.path.join(source, "Testing", "Data") + "/")
    os.makedirs(work, exist_ok=True)
    output = os.path.join(work, "wedge-mesh.vtp")
    if os.path.exists(output):
        os.remove(output)
    script = os.path.join(work, "readme_example.py")
    with open(script, "w") as f:
        f.write(code)
    run = subprocess.run([pvpython, script], cwd=work, capture_output=True, text=True)
    print(run.stdout + run.stderr)
    if run.returncode != 0:
        print("FAILED: the README's pvpython example exited with %d" % run.returncode)
        return 1
    printed = re.search(r"^(\d+) triangles$", run.stdout, re.M)
    if not printed or int(printed.group(1)) == 0:
        print("FAILED: the example did not print a positive triangle count")
        return 1
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(output)
    reader.Update()
    cells = reader.GetOutput().GetNumberOfCells()
    if cells != int(printed.group(1)):
        print("FAILED: %s holds %d triangles, the example printed %s"
              % (output, cells, printed.group(1)))
        return 1
    print("ok: the pvpython example meshed %d triangles and wrote %s" % (cells, output))
    return 0


def check_cpp(readme, source):
    code = code_block(readme, "### 3. From C++", "cpp")
    with open(os.path.join(source, "Testing", "Consumer", "app", "main.cxx")) as f:
        program = {line.strip() for line in f}
    missing = []
    for line in code.splitlines():
        statement = re.sub(r"\s*//.*$", "", line).strip()
        if statement and statement not in program:
            missing.append(statement)
    if missing:
        print("FAILED: lines of the README's C++ example not in Testing/Consumer/app/main.cxx:")
        for line in missing:
            print("  " + line)
        return 1
    print("ok: every line of the README's C++ example is in Testing/Consumer/app/main.cxx")
    return 0


def main(pvpython, readme_path, plugin, source, work):
    with open(readme_path) as f:
        readme = f.read()
    return check_python(pvpython, readme, plugin, source, work) | check_cpp(readme, source)


if __name__ == "__main__":
    if len(sys.argv) != 6:
        print(__doc__)
        sys.exit(2)
    sys.exit(main(*sys.argv[1:]))
