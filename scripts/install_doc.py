"""The install commands of docs/checking.md, as the doc writes them: the ```sh block between the
`<!-- install:begin` and `<!-- install:end` markers. scripts/install_check.sh runs them (through
this module, so the doc and CI's run cannot drift apart) and tests/python/test_install_doc.py
checks that they are there and still parse.

  python3 scripts/install_doc.py DOC                  check the block, print its commands
  python3 scripts/install_doc.py DOC --prefix PATH    check it, print it as a bash script with
                                                      <prefix> replaced by PATH (shell-quoted)

Exits 1 with a message naming the file and the line when the block is missing, doubled, not a
```sh fence, or its commands are not the documented install (configure, build, install to
<prefix>, `<prefix>/bin/curvebench list cases`)."""
import argparse
import os
import re
import shlex
import subprocess
import sys

BEGIN = "<!-- install:begin"
END = "<!-- install:end"
PREFIX = "<prefix>"


class InstallDocError(ValueError):
    """The doc's install block is missing or not the documented install; the message names the file and line."""


def _marker_lines(lines, marker, path):
    found = [i for i, line in enumerate(lines) if line.lstrip().startswith(marker)]
    if not found:
        raise InstallDocError(f"{path}: no line starting with '{marker}' (the install block's marker)")
    if len(found) > 1:
        raise InstallDocError(f"{path}: '{marker}' appears on lines {', '.join(str(i + 1) for i in found)}; "
                              "one install block only")
    return found[0]


def extract(text, path="docs/checking.md"):
    """The install block's command lines, as (line number, text) pairs: every line of the ```sh
    fence between the markers, comments and blank lines included (bash skips them)."""
    lines = text.splitlines()
    begin = _marker_lines(lines, BEGIN, path)
    end = _marker_lines(lines, END, path)
    if end < begin:
        raise InstallDocError(f"{path}:{end + 1}: '{END}' comes before '{BEGIN}' (line {begin + 1})")
    inner = [(i, lines[i]) for i in range(begin + 1, end) if lines[i].strip()]
    if not inner or inner[0][1].strip() != "```sh":
        where = inner[0][0] + 1 if inner else end + 1
        raise InstallDocError(f"{path}:{where}: the install block must open with a ```sh fence right after "
                              f"'{BEGIN}' (line {begin + 1})")
    closes = [i for i, line in inner[1:] if line.strip().startswith("```")]
    if not closes:
        raise InstallDocError(f"{path}:{inner[0][0] + 1}: the install block's ```sh fence is not closed before "
                              f"'{END}' (line {end + 1})")
    if closes[0] != inner[-1][0]:
        raise InstallDocError(f"{path}:{closes[0] + 1}: text after the ```sh fence closes, before '{END}' "
                              f"(line {end + 1}); the block must be the fence alone")
    return [(i + 1, lines[i]) for i in range(inner[0][0] + 1, closes[0])]


def _words(number, line, path):
    try:
        return shlex.split(line, comments=True)
    except ValueError as e:
        raise InstallDocError(f"{path}:{number}: cannot split {line.strip()!r} into words: {e}") from None


def check(commands, options, path="docs/checking.md"):
    """Raises InstallDocError unless the commands parse as bash and are the documented install:
    `cmake -S . -B DIR` (its -DCURVEBENCH_* settings options that CMakeLists.txt declares, `options`),
    `cmake --build DIR`, `cmake --install DIR --prefix <prefix>`, `<prefix>/bin/curvebench list cases`."""
    if not commands:
        raise InstallDocError(f"{path}: the install block's ```sh fence is empty")
    # Parsed as install_check.sh runs it: <prefix> (a redirection to bash) replaced by a path.
    script = "\n".join(line.replace(PREFIX, "/prefix") for _, line in commands) + "\n"
    p = subprocess.run(["bash", "-n"], input=script, capture_output=True, text=True, timeout=60)
    if p.returncode != 0:
        first = commands[0][0]
        # bash names the line of its input: map it back to the doc's.
        detail = re.sub(r"line (\d+)", lambda m: f"line {first + int(m.group(1)) - 1} of {path}",
                        p.stderr.strip().replace("bash: ", ""))
        raise InstallDocError(f"{path}: the install block is not valid bash: {detail}")
    found = {}
    for number, line in commands:
        words = _words(number, line, path)
        # `a && b` on one line: each command on its own.
        for command in (c for c in _split_and(words) if c):
            kind = _kind(command, number, path, options)
            if kind in found:
                raise InstallDocError(f"{path}:{number}: a second {kind} command "
                                      f"(the first is on line {found[kind][0]})")
            found[kind] = (number, command)
    order = ["configure", "build", "install", "list cases"]
    missing = [k for k in order if k not in found]
    if missing:
        raise InstallDocError(f"{path}: the install block has no {' and no '.join(missing)} command")
    lines = [found[k][0] for k in order]
    if lines != sorted(lines):
        raise InstallDocError(f"{path}: the install block's commands are out of order (configure on line {lines[0]}, "
                              f"build {lines[1]}, install {lines[2]}, list cases {lines[3]})")
    tree = _after(found["configure"][1], "-B")
    for kind, flag in (("build", "--build"), ("install", "--install")):
        number, command = found[kind]
        if _after(command, flag) != tree:
            raise InstallDocError(f"{path}:{number}: the {kind} command's tree '{_after(command, flag)}' is not "
                                  f"the configured '{tree}'")


def _after(command, flag):
    """The word after flag in command, or None."""
    i = command.index(flag) if flag in command else len(command)
    return command[i + 1] if i + 1 < len(command) else None


def _split_and(words):
    command = []
    for w in words:
        if w == "&&":
            yield command
            command = []
        else:
            command.append(w)
    yield command


def _kind(command, number, path, options):
    text = " ".join(command)
    if command[0] == "cmake" and "-S" in command:
        if _after(command, "-S") != ".":
            raise InstallDocError(f"{path}:{number}: the configure command must read the checkout's root "
                                  f"(-S .): {text}")
        if _after(command, "-B") is None:
            raise InstallDocError(f"{path}:{number}: the configure command names no build tree (-B DIR): {text}")
        for w in command:
            m = re.match(r"-D(CURVEBENCH_\w+)(?::\w+)?=", w)
            if m and m.group(1) not in options:
                raise InstallDocError(f"{path}:{number}: {m.group(1)} is not an option of CMakeLists.txt "
                                      f"(they are {', '.join(sorted(options))})")
        return "configure"
    if command[:2] == ["cmake", "--build"] and len(command) > 2:
        return "build"
    if command[0] == "cmake" and command[1:2] == ["--install"] and len(command) > 2:
        if command[-2:] != ["--prefix", PREFIX]:
            raise InstallDocError(f"{path}:{number}: the install command must end with --prefix {PREFIX}: {text}")
        return "install"
    if command == [f"{PREFIX}/bin/curvebench", "list", "cases"]:
        return "list cases"
    raise InstallDocError(f"{path}:{number}: not a command of the documented install: {text}")


def cmake_options(cmake_lists_text):
    """The option() names a CMakeLists.txt declares."""
    return set(re.findall(r"^\s*option\(\s*(\w+)", cmake_lists_text, re.MULTILINE))


def as_script(commands, prefix):
    """The commands as a bash script (exit on the first failure), <prefix> replaced by prefix."""
    body = "\n".join(line.replace(PREFIX, shlex.quote(prefix)) for _, line in commands)
    return "set -euo pipefail\nset -x\n" + body + "\n"


def main(argv):
    parser = argparse.ArgumentParser(description="The install block of docs/checking.md.")
    parser.add_argument("doc")
    parser.add_argument("--cmake-lists", help="the CMakeLists.txt whose options the block may set "
                        "(default: the one at the doc's checkout root)")
    parser.add_argument("--prefix", help="print the block as a bash script with <prefix> replaced by this path")
    args = parser.parse_args(argv)
    cmake_lists = args.cmake_lists or os.path.join(os.path.dirname(os.path.abspath(args.doc)), "..", "CMakeLists.txt")
    try:
        with open(args.doc, encoding="utf-8") as f:
            text = f.read()
        with open(cmake_lists, encoding="utf-8") as f:
            options = cmake_options(f.read())
        commands = extract(text, args.doc)
        check(commands, options, args.doc)
    except (OSError, InstallDocError) as e:
        print(f"install_doc.py: {e}", file=sys.stderr)
        return 1
    if args.prefix is not None:
        sys.stdout.write(as_script(commands, args.prefix))
    else:
        sys.stdout.write("".join(line + "\n" for _, line in commands))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
