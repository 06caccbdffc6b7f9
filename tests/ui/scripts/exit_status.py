# sylva.quit(code) leaves the editor with that status.
import sylva
sylva.quit(3)
