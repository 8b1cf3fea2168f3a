#!/usr/bin/python3
"""Why each failed ctest test failed, in a few lines, for the end of scripts/test.sh's output.

A failing rostest's own output can run to thousands of lines (TF warnings of a replayed bag), so a
log that keeps only its tail loses the assertion. This prints, per failed test, the lines that say
why (assertions, gtest failures, exceptions), shortened. Usage: failure_digest.py BUILD_DIR
"""
import os
import re
import sys

WHY = re.compile(r"AssertionError|Error:|\[  FAILED  \]|Failure$|FAILURE|RuntimeError|Exception|"
                 r"Expected|Which is|[Tt]imed? ?out|Segmentation|Aborted|failed with|has died")
LINES_PER_TEST = 8
CHARACTERS_PER_LINE = 600


def failed_tests(temporary):
    path = os.path.join(temporary, "LastTestsFailed.log")
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [line.strip().split(":", 1)[1] for line in f if ":" in line]


def sections(log_text):
    """Each test's output in LastTest.log, by test name."""
    found = {}
    for match in re.finditer(r"^\d+/\d+ Test: (\S+)\n(.*?)^Test (?:Passed|Failed)", log_text, re.M | re.S):
        found[match.group(1)] = match.group(2)
    return found


def main():
    temporary = os.path.join(sys.argv[1], "Testing", "Temporary")
    names = failed_tests(temporary)
    if not names:
        return
    with open(os.path.join(temporary, "LastTest.log"), errors="replace") as f:
        outputs = sections(f.read())
    for name in names:
        reasons, seen = [], set()
        for line in outputs.get(name, "").splitlines():
            line = re.sub(r"\x1b\[[0-9;]*m", "", line).strip()
            if WHY.search(line) and "TF_OLD_DATA" not in line and line not in seen:
                seen.add(line)
                reasons.append(line[:CHARACTERS_PER_LINE])
        print("why %s failed:" % name)
        for reason in reasons[-LINES_PER_TEST:] or ["(no assertion found in its output; see LastTest.log)"]:
            print("  " + reason)


if __name__ == "__main__":
    main()
