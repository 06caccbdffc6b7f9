# An exception ends the script with status 1 and its traceback on stderr.
import sylva
sylva.document().add_tree("no-such-species", (0, 0, 0))
