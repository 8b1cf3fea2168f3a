"""Running one of this package's nodes to its end, as the bad-parameter cases of the rostests do."""
import subprocess

import roslib.packages


def run_node(node_type, *arguments):
    """Runs dressed_human's `node_type` with `arguments` until it exits (at most 30 s): its exit
    code and its output (stdout and stderr together)."""
    executable = roslib.packages.find_node("dressed_human", node_type)[0]
    result = subprocess.run([executable] + list(arguments), stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            timeout=30, universal_newlines=True)
    return result.returncode, result.stdout
