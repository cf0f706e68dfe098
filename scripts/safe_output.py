"""Writing the scripts' output files (REPORT.md, its plots, docs/results.md, the peers' results) as
the tool writes its own (bench/harness/writers.hpp): only a regular file or a new path is ever
replaced; a directory, a symbolic link, a FIFO, a device or a socket is refused by name and left as
it was. The text goes to a new temporary file beside the target, created exclusively (never an
existing name, never through a link), then renamed over it, so an interrupted run never leaves a
half-written file."""
import os
import stat
import tempfile

_KINDS = [(stat.S_ISDIR, "a directory"), (stat.S_ISLNK, "a symbolic link"), (stat.S_ISFIFO, "a FIFO"),
          (stat.S_ISCHR, "a character device"), (stat.S_ISBLK, "a block device"), (stat.S_ISSOCK, "a socket")]


class OutputError(OSError):
    """An output path that cannot or must not be written; the message names the path."""


def check_output_path(path):
    """Raises OutputError when path exists and is not a regular file."""
    if not path:
        raise OutputError("an empty output path")
    try:
        mode = os.lstat(path).st_mode
    except FileNotFoundError:
        return
    if stat.S_ISREG(mode):
        return
    kind = next((name for test, name in _KINDS if test(mode)), "not a regular file")
    raise OutputError(f"{path}: is {kind}; outputs are written only to a regular file or a new path")


def write_with(path, write):
    """Calls write(temporary_path) to fill a new file beside path, then renames it over path."""
    check_output_path(path)
    directory = os.path.dirname(path) or "."
    fd, tmp = tempfile.mkstemp(dir=directory, prefix=os.path.basename(path) + ".", suffix=".tmp")
    os.close(fd)
    try:
        write(tmp)
        mask = os.umask(0)
        os.umask(mask)
        os.chmod(tmp, 0o666 & ~mask)  # mkstemp's 0600 would hide the output from others
        check_output_path(path)  # again: the path may have been replaced during the work
        os.replace(tmp, path)
    except BaseException:
        if os.path.lexists(tmp):
            os.unlink(tmp)
        raise


def write_text(path, text):
    """text (UTF-8) at path, through write_with."""
    def write(tmp):
        with open(tmp, "w", encoding="utf-8") as f:
            f.write(text)
    write_with(path, write)
