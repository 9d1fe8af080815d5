"""The commit measured (machine.txt) and how to list what has changed in the measured code since.
The report depends only on its raw results and the repository's files, never on the commit it
is written at: how many files have changed goes to the console, not the report."""
import subprocess

# What the benchmarks measure: a change here since the commit measured makes the report stale.
MEASURED_CODE = ["src", "include", "bench/*.cpp", "bench/*.h", "bench/*.py", "CMakeLists.txt", "config", "urdf"]


def commit_measured(machine):
    """The commit machine.txt names ("commit:   f879a66 (with uncommitted changes)"), or None."""
    return next((line.split()[1] for line in machine.splitlines() if line.startswith("commit:")), None)


def code_since(root, text, machine, command="scripts/bench"):
    """The report's line on the code measured, and the count of its files changed since on the
    console."""
    commit = commit_measured(machine)
    if commit is None:
        return []
    result = subprocess.run(["git", "-C", root, "diff", "--name-only", commit, "HEAD", "--", *MEASURED_CODE],
                            capture_output=True, text=True)
    if result.returncode != 0:
        print(f"bench_report: the commit measured, {commit}, is not in this repository's history")
    else:
        changed = [name for name in result.stdout.splitlines() if name]
        print(f"bench_report: {len(changed)} files of the measured code have changed since the commit measured, "
              f"{commit}" + (f" (`{command}` re-measures)" if changed else ""))
    quoted = " ".join(f"'{path}'" if "*" in path else path for path in MEASURED_CODE)
    return [text("measured_code", paths=" ".join(MEASURED_CODE), commit=commit, quoted=quoted, command=command), ""]
