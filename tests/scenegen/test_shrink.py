"""The shrinker on a synthetic predicate (no vct): a scene "fails" when it holds one chosen
triangle of one chosen mesh, a spot light and the setting `bounces`. The shrinker must reach
exactly that and nothing more, so it cannot silently do nothing (issue 34, item 2)."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "tools", "scenegen"))
import generate  # noqa: E402
import shrink  # noqa: E402


def culprit_scene():
    spec = generate.generate(4, "small")  # a room, planes, a heightfield: 5 meshes
    spec["settings"]["bounces"] = 2
    spec["lights"].append({"name": "culprit_spot", "type": "spot", "color": [1, 1, 1], "intensity": 3.0,
                           "inner": 0.2, "outer": 0.5, "translation": [0, 1, 0], "rotation": None})
    mesh = max(spec["meshes"], key=lambda m: len(m["indices"]))
    tri = mesh["indices"][len(mesh["indices"]) // 3]
    return spec, mesh["name"], mesh["positions"][tri].copy()


def make_predicate(name, corners, calls):
    def still_fails(spec):
        calls.append(1)
        has_light = any(l["type"] == "spot" for l in spec["lights"])
        has_setting = "bounces" in spec["settings"]
        has_tri = any(m["name"] == name and any(np.array_equal(m["positions"][t], corners) for t in m["indices"])
                      for m in spec["meshes"])
        return has_light and has_setting and has_tri
    return still_fails


def test_shrinks_to_the_culprit():
    spec, name, corners = culprit_scene()
    before = sum(len(m["indices"]) for m in spec["meshes"])
    assert before > 100 and len(spec["meshes"]) >= 3 and len(spec["lights"]) >= 2
    calls = []
    small, count = shrink.shrink(spec, make_predicate(name, corners, calls), budget=2000)
    assert count == len(calls) and count > 10
    assert [m["name"] for m in small["meshes"]] == [name]
    assert len(small["meshes"][0]["indices"]) == 1
    assert np.array_equal(small["meshes"][0]["positions"][small["meshes"][0]["indices"][0]], corners)
    assert [l["type"] for l in small["lights"]] == ["spot"]
    assert small["settings"] == {"bounces": 2}
    assert (small["width"], small["height"], small["grid"]) == (spec["width"] // 2 ** int(np.log2(spec["width"] // 8)),
                                                                spec["height"] // 2 ** int(np.log2(spec["height"] // 8)), 16)
    assert small["shadow_map_size"] == 64
    assert small["textures"] == [] and len(small["materials"]) == 1
    assert make_predicate(name, corners, [])(small)


def test_budget_is_respected_and_result_still_fails():
    spec, name, corners = culprit_scene()
    calls = []
    small, count = shrink.shrink(spec, make_predicate(name, corners, calls), budget=7)
    assert count == len(calls) == 7
    assert make_predicate(name, corners, [])(small)


def test_nothing_to_drop_when_everything_matters():
    spec, name, corners = culprit_scene()
    calls = []
    small, _ = shrink.shrink(spec, lambda s: calls.append(1) or False, budget=50)
    assert small is spec and len(calls) == 50


def world_bounds(spec):
    points = np.concatenate([generate.world_points(m, m["positions"][m["indices"].reshape(-1)])
                             for m in spec["meshes"] if len(m["indices"])])
    return points.min(axis=0), points.max(axis=0)


def test_pinned_bounds_keep_the_scene_box_and_the_culprit():
    spec, name, corners = culprit_scene()
    small, _ = shrink.shrink(spec, make_predicate(name, corners, []), budget=2000, pin=True)
    lo, hi = world_bounds(spec)
    small_lo, small_hi = world_bounds(small)
    assert np.array_equal(lo, small_lo) and np.array_equal(hi, small_hi)
    assert make_predicate(name, corners, [])(small)
    # The culprit and at most one triangle per extreme (six), nothing else: the pins do not stop
    # the rest from going.
    kept = sum(len(m["indices"]) for m in small["meshes"])
    assert 2 <= kept <= 7 and sum(int(m["pinned"].sum()) for m in small["meshes"]) == kept - 1
    # Unpinned, the same predicate leaves the culprit alone and the box shrinks to it.
    alone, _ = shrink.shrink(spec, make_predicate(name, corners, []), budget=2000)
    assert not np.array_equal(world_bounds(alone)[1] - world_bounds(alone)[0], hi - lo)
