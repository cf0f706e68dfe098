"""The documented install (docs/checking.md's block between `<!-- install:begin` and
`<!-- install:end`), which CI runs as written (scripts/install_check.sh through
scripts/install_doc.py): the block is there, parses as bash, is the install (configure, build,
install to <prefix>, the installed tool's `list cases`) and sets only options CMakeLists.txt
declares; a doc whose markers, fence or commands drifted is refused naming the file and line. The
build it documents must not need the user to turn -Werror off: CURVEBENCH_WERROR is off by default
and scripts/test.sh turns it on for its own builds."""
import os
import re
import shlex
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import install_doc  # noqa: E402
from test_scripts import usage_comment  # noqa: E402

DOC = os.path.join(ROOT, "docs", "checking.md")


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


OPTIONS = install_doc.cmake_options(read(os.path.join(ROOT, "CMakeLists.txt")))

GOOD = """Some text.

<!-- install:begin -->
```sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DCURVEBENCH_BUILD_TESTS=OFF
cmake --build build
cmake --install build --prefix <prefix>   # the package
<prefix>/bin/curvebench list cases
```
<!-- install:end -->
More text.
"""


def commands_of(text):
    commands = install_doc.extract(text, "doc.md")
    install_doc.check(commands, OPTIONS, "doc.md")
    return commands


class TheDocsBlock(unittest.TestCase):
    def test_block_is_the_install(self):
        commands = install_doc.extract(read(DOC), DOC)
        install_doc.check(commands, OPTIONS, DOC)
        words = [w for _, line in commands for w in shlex.split(line, comments=True)]
        # An install needs neither the GoogleTest suite (the larger part of the build) nor the
        # user's turning -Werror off.
        self.assertIn("-DCURVEBENCH_BUILD_TESTS=OFF", words)
        self.assertIn("-DCURVEBENCH_BUILD_BENCH=ON", words)
        self.assertFalse([w for w in words if "WERROR" in w], words)

    def test_werror_is_off_by_default_and_on_in_test_sh(self):
        cmake = read(os.path.join(ROOT, "CMakeLists.txt"))
        m = re.search(r"^option\(CURVEBENCH_WERROR \"[^\"]*\" (\w+)\)", cmake, re.MULTILINE)
        self.assertIsNotNone(m, "CMakeLists.txt declares no CURVEBENCH_WERROR option")
        self.assertEqual(m.group(1), "OFF")
        test_sh = read(os.path.join(ROOT, "scripts", "test.sh"))
        # Each configure command of test.sh (its continuation lines joined) asks for -Werror.
        configures = re.findall(r"^\s*cmake -S .*?(?<!\\)$", test_sh.replace("\\\n", " "), re.MULTILINE)
        self.assertEqual(len(configures), 2, configures)
        for c in configures:
            self.assertIn("-DCURVEBENCH_WERROR=ON", c)

    def test_script_substitutes_the_prefix(self):
        commands = install_doc.extract(read(DOC), DOC)
        script = install_doc.as_script(commands, "/tmp/a prefix")
        self.assertNotIn("<prefix>", script)
        self.assertIn("--prefix '/tmp/a prefix'", script)
        self.assertIn("'/tmp/a prefix'/bin/curvebench list cases", script)
        p = subprocess.run(["bash", "-n"], input=script, capture_output=True, text=True, timeout=60)
        self.assertEqual(p.returncode, 0, p.stderr)


class DriftIsRefused(unittest.TestCase):
    def refused(self, text, *fragments):
        with self.assertRaises(install_doc.InstallDocError) as e:
            commands_of(text)
        message = str(e.exception)
        self.assertIn("doc.md", message)
        for f in fragments:
            self.assertIn(f, message)
        return message

    def test_good_block_passes(self):
        self.assertEqual([n for n, _ in commands_of(GOOD)], [5, 6, 7, 8])

    def test_markers(self):
        self.refused(GOOD.replace("<!-- install:begin -->\n", ""), "<!-- install:begin")
        self.refused(GOOD.replace("<!-- install:end -->\n", ""), "<!-- install:end")
        self.refused(GOOD + GOOD, "lines 3, 14")
        begin, end = "<!-- install:begin -->", "<!-- install:end -->"
        self.refused(GOOD.replace(begin, "@@").replace(end, begin).replace("@@", end), "doc.md:3", "comes before")

    def test_fence(self):
        self.refused(GOOD.replace("```sh", "```cmake"), "doc.md:4", "```sh")
        self.refused(GOOD.replace("```\n<!-- install:end", "<!-- install:end"), "not closed")
        self.refused(GOOD.replace("```\n<!-- install:end", "```\nand text\n<!-- install:end"), "doc.md:9", "text after")

    def test_commands_that_do_not_parse(self):
        # bash's own complaint, at the doc's line.
        self.refused(GOOD.replace("cmake --build build", "cmake --build build && && true"), "line 6 of doc.md")
        self.refused(GOOD.replace("cmake --build build", "cmake --build 'build"), "not valid bash")

    def test_commands_that_are_not_the_install(self):
        self.refused(GOOD.replace("-DCURVEBENCH_BUILD_TESTS=OFF", "-DCURVEBENCH_BUILD_TEST=OFF"), "doc.md:5",
                     "CURVEBENCH_BUILD_TEST is not an option")
        self.refused(GOOD.replace("--prefix <prefix>", "--prefix /usr/local"), "doc.md:7", "--prefix <prefix>")
        self.refused(GOOD.replace("<prefix>/bin/curvebench list cases\n", ""), "no list cases command")
        self.refused(GOOD.replace("cmake --build build\n", ""), "no build command")
        self.refused(GOOD.replace("cmake --build build", "cmake --build build2"), "doc.md:6", "'build2'")
        self.refused(GOOD.replace("-S .", "-S src"), "doc.md:5", "-S .")
        self.refused(GOOD.replace("cmake --build build\n", "cmake --build build\nmake install\n"), "doc.md:7",
                     "not a command of the documented install")
        moved = GOOD.replace("cmake --build build\n", "").replace("list cases\n", "list cases\ncmake --build build\n")
        self.refused(moved, "out of order")
        self.refused(GOOD.replace("```sh\n", "```sh\ncmake --build build\n"), "second build command")

    def test_one_line_configure_and_build(self):
        joined = GOOD.replace("OFF\ncmake --build build", "OFF && cmake --build build")
        self.assertEqual(len(commands_of(joined)), 3)

    def test_command_line(self):
        with tempfile.TemporaryDirectory() as d:
            os.makedirs(os.path.join(d, "docs"))
            doc = os.path.join(d, "docs", "checking.md")
            with open(os.path.join(d, "CMakeLists.txt"), "w", encoding="utf-8") as f:
                f.write('option(CURVEBENCH_BUILD_TESTS "tests" ON)\n')
            with open(doc, "w", encoding="utf-8") as f:
                f.write(GOOD.replace("<!-- install:end -->\n", ""))
            p = subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "install_doc.py"), doc],
                               capture_output=True, text=True, timeout=60)
            self.assertEqual(p.returncode, 1)
            self.assertIn(doc, p.stderr)
            self.assertIn("<!-- install:end", p.stderr)
            with open(doc, "w", encoding="utf-8") as f:
                f.write(GOOD)
            p = subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "install_doc.py"), doc,
                                "--prefix", "/opt/cb"], capture_output=True, text=True, timeout=60)
            self.assertEqual(p.returncode, 0, p.stderr)
            self.assertIn("cmake --install build --prefix /opt/cb", p.stdout)
            self.assertIn("/opt/cb/bin/curvebench list cases", p.stdout)


class InstallCheckUsage(unittest.TestCase):
    """install_check.sh --help prints its usage comment; an argument is a usage error (exit 2)
    before anything is installed or built."""

    def test_help_and_bad_argument(self):
        path = os.path.join(ROOT, "scripts", "install_check.sh")
        p = subprocess.run(["bash", path, "--help"], capture_output=True, text=True, timeout=60)
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertIn("scripts/install_check.sh", p.stdout)
        self.assertNotIn("set -euo pipefail", p.stdout)
        self.assertEqual(p.stdout.splitlines(), usage_comment(path))
        p = subprocess.run(["bash", path, "--fast"], capture_output=True, text=True, timeout=60)
        self.assertEqual(p.returncode, 2)
        self.assertIn("'--fast'", p.stderr)


if __name__ == "__main__":
    unittest.main()
