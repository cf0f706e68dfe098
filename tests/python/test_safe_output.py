"""scripts/safe_output.py, the one write path of the scripts' outputs: a new path
and a regular file are replaced whole with no temporary left; a FIFO, a symbolic link, a directory
are refused by name and left as they were; a device is refused by the check alone (were the check
broken, a write would replace it with a regular file when run as root)."""
import os
import stat
import sys
import tempfile
import unittest

SCRIPTS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts")
sys.path.insert(0, SCRIPTS)
sys.path.insert(0, os.path.join(SCRIPTS, "peers"))
import peer_io  # noqa: E402
import safe_output  # noqa: E402


class SafeOutputTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.addCleanup(self.dir.cleanup)

    def at(self, name):
        return os.path.join(self.dir.name, name)

    def test_new_and_regular_files_are_replaced_whole(self):
        p = self.at("REPORT.md")
        safe_output.write_text(p, "one\n")
        safe_output.write_text(p, "two\n")
        with open(p, encoding="utf-8") as f:
            self.assertEqual(f.read(), "two\n")
        peer_io.write_json(self.at("peers.json"), {"a": 1})
        with open(self.at("peers.json"), encoding="utf-8") as f:
            self.assertEqual(f.read(), '{\n "a": 1\n}')
        self.assertEqual(sorted(os.listdir(self.dir.name)), ["REPORT.md", "peers.json"])

    def test_fifo_link_and_directory_are_refused_and_kept(self):
        fifo = self.at("pipe")
        os.mkfifo(fifo)
        with self.assertRaisesRegex(safe_output.OutputError, "pipe: is a FIFO; outputs are written only"):
            safe_output.write_text(fifo, "x")
        self.assertTrue(stat.S_ISFIFO(os.lstat(fifo).st_mode))
        target, link = self.at("target"), self.at("link")
        safe_output.write_text(target, "kept")
        os.symlink(target, link)
        with self.assertRaisesRegex(safe_output.OutputError, "link: is a symbolic link"):
            peer_io.write_json(link, {})
        self.assertTrue(os.path.islink(link))
        with open(target, encoding="utf-8") as f:
            self.assertEqual(f.read(), "kept")
        os.mkdir(self.at("sub"))
        with self.assertRaisesRegex(safe_output.OutputError, "sub: is a directory"):
            safe_output.write_text(self.at("sub"), "x")
        self.assertEqual(sorted(os.listdir(self.dir.name)), ["link", "pipe", "sub", "target"])

    def test_a_device_is_refused_by_the_check(self):
        self.assertTrue(stat.S_ISCHR(os.lstat("/dev/null").st_mode))
        with self.assertRaisesRegex(safe_output.OutputError, "/dev/null: is a character device"):
            safe_output.check_output_path("/dev/null")

    def test_a_failed_write_leaves_no_temporary(self):
        def fail(tmp):
            raise ValueError("stopped")
        with self.assertRaises(ValueError):
            safe_output.write_with(self.at("plot.png"), fail)
        self.assertEqual(os.listdir(self.dir.name), [])


if __name__ == "__main__":
    unittest.main()
