# win.project() right after the editor opens answers for the window as it will be shown: the
# first thing this script does is ask, before the event loop has laid out the docks (the
# viewport was still 557 px wide, later 393: a point drawn at x=537 was reported at x=619, and
# an outside tool clicking there missed). The same after a resize and after the species
# editor's dock opens. Run by run_scripts.sh.
import sylva

doc = sylva.document()
win = sylva.window()
points = [t.position for t in doc.trees()] + [(10, 0, 10), (-10, 5, -10), (20, 0, -5)]


def check(when):
    first = [win.project(*p) for p in points]
    sylva.wait(1.0)  # laid out, resized and painted
    later = [win.project(*p) for p in points]
    assert any(p is not None for p in later), "nothing in view"
    for p, a, b in zip(points, first, later):
        assert (a is None) == (b is None), (when, p, a, b)
        if a is not None:
            assert abs(a[0] - b[0]) <= 1 and abs(a[1] - b[1]) <= 1, (when, p, a, b)


check("after opening")
win.resize(1200, 800)
check("after a resize")
win.edit_species(doc.trees()[0].species)  # the Species Editor's dock takes space from the view
check("after opening the species editor")
print("project() before the layout: ok")
sylva.quit(0)
