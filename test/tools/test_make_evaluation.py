#!/usr/bin/env python3
"""scripts/make_evaluation.py publishes one whole run of scripts/evaluate.sh or nothing (issue 37):
a run that did not finish, a run of a commit the tree does not hold, and a finished run with an
input missing are each refused with a message naming why, and leave docs/ and the README as they
were. Runs a copy of the script in a scratch repository (its ROOT is where it lies), so that a
refusal that failed could not touch this tree.

Usage: test_make_evaluation.py <repository root>
"""
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else "."
sys.argv[1:] = sys.argv[2:]
README = ("# x\n\n<!-- Written by scripts/make_evaluation.py from one run of scripts/evaluate.sh: edit it there. -->\n"
          "old speed\n<!-- End of the section written by scripts/make_evaluation.py. -->\n")


def git(repository, *arguments):
    return subprocess.run(["git", "-C", repository] + list(arguments), check=True, stdout=subprocess.PIPE,
                          universal_newlines=True).stdout.strip()


class MakeEvaluationRefuses(unittest.TestCase):
    def setUp(self):
        self.tree = tempfile.mkdtemp()
        os.makedirs(os.path.join(self.tree, "scripts"))
        os.makedirs(os.path.join(self.tree, "docs"))
        shutil.copy(os.path.join(ROOT, "scripts", "make_evaluation.py"), os.path.join(self.tree, "scripts"))
        shutil.copytree(os.path.join(ROOT, "config", "motions"), os.path.join(self.tree, "config", "motions"))
        with open(os.path.join(self.tree, "README.md"), "w") as f:
            f.write(README)
        with open(os.path.join(self.tree, "docs", "stability.md"), "w") as f:
            f.write("# Stability\n\ntext\n")
        git(self.tree, "init", "-q")
        git(self.tree, "add", ".")
        git(self.tree, "-c", "user.name=t", "-c", "user.email=t@t", "commit", "-q", "-m", "scratch")
        self.run_dir = os.path.join(self.tree, "build", "evaluation", "run")
        # Every input of a real run, copied from this tree's last published one where it has them.
        shutil.copytree(os.path.join(ROOT, "docs"), os.path.join(self.run_dir, "docs"),
                        ignore=shutil.ignore_patterns("*.png", "EVALUATION.md"))

    def tearDown(self):
        shutil.rmtree(self.tree)

    def write_record(self, commit, finished=True):
        lines = ["command: scripts/evaluate.sh", "commit: " + commit, "started: 2026-01-01T00:00:00Z",
                 "host: scratch, 2 cores"]
        if finished:
            lines.append("finished: 2026-01-01T01:00:00Z, 3600 s after it started")
        with open(os.path.join(self.run_dir, "run.txt"), "w") as f:
            f.write("\n".join(lines) + "\n")

    def refused(self, reason):
        before = sorted(os.listdir(os.path.join(self.tree, "docs")))
        result = subprocess.run([sys.executable, os.path.join(self.tree, "scripts", "make_evaluation.py"), self.run_dir],
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
        self.assertNotEqual(result.returncode, 0, result.stdout)
        self.assertIn(reason, result.stdout)
        self.assertEqual(sorted(os.listdir(os.path.join(self.tree, "docs"))), before, "docs/ changed")
        with open(os.path.join(self.tree, "README.md")) as f:
            self.assertEqual(f.read(), README, "README changed")

    def test_a_run_that_did_not_finish_is_refused(self):
        self.write_record(git(self.tree, "rev-parse", "HEAD"), finished=False)
        self.refused("did not finish")

    def test_a_run_of_a_commit_this_tree_lacks_is_refused(self):
        self.write_record("0123456789abcdef0123456789abcdef01234567")
        self.refused("not in this tree's history")

    def test_a_finished_run_missing_an_input_is_refused_before_anything_is_published(self):
        self.write_record(git(self.tree, "rev-parse", "HEAD"))
        # The benchmark JSONs and CSVs live beside docs/ in a run's folder: none are there.
        self.refused("missing input")


if __name__ == "__main__":
    unittest.main()
