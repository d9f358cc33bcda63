"""The stage registry as the run wrote it (run.json["stage_registry"]: ref/stages/stage_registry.cpp,
one row per stage; `vct stages --json` prints the same). The report keeps no list of stage names of
its own: it asks this table what a stage is, where it is documented and which walkthrough step
shows it. The few stages the report shows by role are named once, below, and checked against the
table so a rename in the registry fails loudly instead of silently dropping a figure."""

FINAL = "image.final"              # the final frame (the registry row whose path-tracer AOV is pt_full)
VOXEL_RADIANCE = "voxel.radiance"  # the base voxel level (tolerance model voxel_radiance)
VOXEL_EXTRA = ("voxel.conservative", "voxel.fragments")  # reference-side voxel inputs shown beside it
VOXEL_DERIVED = ("voxel.occupancy", "voxel.holes")        # judged, made by the judge


class Registry:
    def __init__(self, rows):
        self.rows = list(rows or [])
        self.by_name = {r["name"]: r for r in self.rows}
        missing = [n for n in (FINAL, VOXEL_RADIANCE) + VOXEL_EXTRA + VOXEL_DERIVED
                   if self.rows and n not in self.by_name]
        if missing:
            raise ValueError("stage registry lacks %s (report/vct_report/registry.py names them)" % ", ".join(missing))

    def row(self, stage):
        """The row of a stage or family member ("mip.iso.3" -> the "mip.iso" row); None if unknown."""
        if stage in self.by_name:
            return self.by_name[stage]
        head, _, tail = stage.rpartition(".")
        r = self.by_name.get(head)
        return r if r and r.get("family") and tail.isdigit() else None

    def doc(self, stage):
        """(what, docs, ref source, gl source) for a stage, None when the registry does not know it."""
        r = self.row(stage)
        if not r:
            return None
        return r["what"], r["docs"], r["ref_source"], r["gl_source"]

    def step_prefixes(self, step):
        """Name prefixes of the stages a walkthrough step shows, in pipeline order (families end in '.')."""
        return [r["name"] + ("." if r.get("family") else "") for r in self.rows if r.get("walkthrough_step") == step]


def from_run(run_json):
    return Registry((run_json or {}).get("stage_registry"))
