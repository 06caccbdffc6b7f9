# SIGTERM (or Ctrl-C) while a script waits stops it there, with a traceback that names the
# wait: run_scripts.sh sends SIGTERM once this prints "waiting". A script in sylva.wait(500)
# (500 seconds, meant as milliseconds) used to die silently under `timeout`, and looked like a
# hang of the undo calls that came after it.
import sylva


def keep_the_window_open():
    sylva.wait(600)


print("waiting", flush=True)
keep_the_window_open()
print("the wait was not interrupted", flush=True)
