"""What the Python rostests share: waiting on a condition with a deadline (never sleeping to
synchronise), and running a command as a user types it. A mixin for unittest.TestCase."""
import subprocess
import time


class RosTestSupport:
    def wait_for(self, condition, seconds, what):
        """Polls `condition` until it holds; fails naming `what` after `seconds`."""
        deadline = time.time() + seconds
        while not condition() and time.time() < deadline:
            time.sleep(0.05)  # polls within the deadline
        self.assertTrue(condition(), "waited %.0f s for %s" % (seconds, what))

    def run_command(self, command):
        """Runs `command` (a list) as a user types it; asserts it exits 0; returns its output."""
        done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=60,
                              universal_newlines=True)
        self.assertEqual(done.returncode, 0, "%s failed:\n%s" % (" ".join(command), done.stdout))
        return done.stdout
