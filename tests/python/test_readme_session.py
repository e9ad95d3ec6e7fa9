"""The notebook session of the README, run as written from the repository
root: it must work and print what it says."""
import os
import re
import subprocess
import sys
import unittest
from pathlib import Path

SOURCE = Path(os.environ["HYSTBENCH_SOURCE_DIR"])


def session() -> str:
    readme = (SOURCE / "README.md").read_text(encoding="utf-8")
    blocks = re.findall(r"```python\n(.*?)```", readme, re.S)
    if len(blocks) != 1:
        raise AssertionError(f"README.md has {len(blocks)} python blocks, not one")
    return blocks[0]


class ReadmeSession(unittest.TestCase):
    def test_is_at_most_ten_lines(self):
        self.assertLessEqual(len(session().strip().splitlines()), 10)

    def test_runs_from_the_repository_root(self):
        before = set(os.listdir(SOURCE))
        r = subprocess.run([sys.executable, "-c", session()], cwd=SOURCE, capture_output=True,
                           text=True, env=os.environ)
        self.assertEqual(r.returncode, 0, r.stderr)
        printed = r.stdout.strip().splitlines()
        self.assertEqual(len(printed), session().count("print("), r.stdout)
        self.assertEqual(set(os.listdir(SOURCE)), before, "the session left files behind")


if __name__ == "__main__":
    unittest.main()
