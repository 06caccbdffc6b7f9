# Run by test_python_embedded: the editor's way of getting the engine functions.
import os
import sylva

assert sylva.embedded()
species = sylva.load_species(os.path.join(sylva.presets_dir(), "ternary-tree.json"))
tree = species.grow(seed=1)
assert tree.mesh.vertex_count > 0 and len(tree.skeleton) > 0
try:
    species.set_param("grow.bogus", 1)
    raise SystemExit("no ValueError")
except ValueError as e:
    assert "has no parameter 'bogus'" in str(e)
print("embedded sylva:", tree)
for name in ("Tree", "Document", "Window", "document", "window", "Species", "GrownTree",
             "Project", "Forest", "ForestTree", "Mesh", "Skeleton", "load_species",
             "load_project", "grow"):
    assert hasattr(sylva, name), name
