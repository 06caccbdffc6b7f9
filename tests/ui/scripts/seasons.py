# Seasons change what the viewport draws (issue #33): an English oak alone in the view, shot in
# summer, autumn (the project's season), winter and, as the tree's own season, spring. The
# crown's pixels are those winter (bare) does not cover; in them autumn is redder than summer,
# spring a lighter green, winter shows the sky. Each season is one undo step; undoing them
# gives back the exact project. Run by run_scripts.sh through `sylva --script`.
import os

import numpy as np
import sylva

doc = sylva.document()
win = sylva.window()
out = os.environ["SYLVA_TEST_OUT"]
original = doc.serialized()
doc.add_species("oak", os.path.join(os.environ["SYLVA_PRESETS_DIR"], "english-oak.json"))
tree = doc.add_tree("oak", (400, 0, 400), seed=1)


def read_ppm(path):
    with open(path, "rb") as f:
        data = f.read()
    parts = data.split(maxsplit=4)
    assert parts[0] == b"P6", parts[0]
    w, h = int(parts[1]), int(parts[2])
    pixels = np.frombuffer(parts[4][:w * h * 3], np.uint8)
    return pixels.reshape(h, w, 3).astype(np.float64)


def shot(name):
    doc.generate()
    win.look_from((400, 7, 422), (400, 6.5, 400))  # after the regrowth, which frames the view
    sylva.wait(1.0)  # the new meshes uploaded and drawn
    path = os.path.join(out, "season-%s.ppm" % name)
    win.screenshot(path, viewport_only=True)
    return read_ppm(path)


shot("first")  # the first generation frames the view once more after it is shown
summer = shot("summer")
doc.season = "autumn"
assert doc.season == "autumn"
autumn = shot("autumn")
doc.season = "winter"
winter = shot("winter")
doc.set_tree(tree, season="spring")  # the tree's own season wins over the project's winter
assert doc.tree(tree).season == "spring"
spring = shot("spring")
assert doc.undo_texts()[-3:] == ["Change season", "Change season", "Change tree season"], \
    doc.undo_texts()

crown = np.abs(summer - winter).sum(axis=2) > 60  # leaves in summer, sky or bark in winter
assert crown.sum() > 2000, "the summer oak covers only %d pixels the bare one does not" % crown.sum()


def redness(image):
    """Mean red / green over the crown's pixels that are not the sky."""
    leafy = crown & (np.abs(image - winter).sum(axis=2) > 60)
    r, g = image[leafy][:, 0].mean(), image[leafy][:, 1].mean()
    return r / g, leafy.sum(), g


summer_red, summer_n, summer_g = redness(summer)
autumn_red, autumn_n, _ = redness(autumn)
spring_red, spring_n, spring_g = redness(spring)
print("crown pixels %d: red/green summer %.2f (%d), autumn %.2f (%d), spring %.2f (%d)"
      % (crown.sum(), summer_red, summer_n, autumn_red, autumn_n, spring_red, spring_n))
assert summer_red < 0.9, "summer leaves are not green: red/green %.2f" % summer_red
assert autumn_red > summer_red + 0.3, "autumn is not redder: %.2f vs %.2f" % (autumn_red, summer_red)
# Fewer leaves in autumn and spring than in summer.
assert autumn_n < summer_n and spring_n < summer_n, (summer_n, autumn_n, spring_n)
assert spring_g > summer_g, "spring leaves are not a lighter green: %.0f vs %.0f" % (spring_g, summer_g)

while doc.undo_count() > 0:
    doc.undo()
assert doc.serialized() == original
sylva.quit(0)
