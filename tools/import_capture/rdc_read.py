#!/usr/bin/python3
"""Reads textures out of a RenderDoc capture for `vct import-capture` (app/renderdoc_reader.cpp).

    /usr/bin/python3 rdc_read.py CAPTURE.rdc REQUEST.json OUTDIR

REQUEST.json: {"stages": [{"name", "resource", "event", "mip", "slice", "sample"}, ...]} (the
capture map's stages, compare/capture_map.h). For each stage, in order, the texture is read after
its event and written to OUTDIR/<i>.f32 as little-endian float32 (channels fastest, then x, then
y in the API's row order, then z), converted as docs/external_format.md says (UNORM / (2^bits - 1),
depth in [0,1], half and float as stored, integers as their value); OUTDIR/index.json lists
{width, height, depth, channels, format} per stage.

Runs under the system python3, not the project's venv: python3-renderdoc (Debian) is an extension
module built for Debian's python3 and installed in its dist-packages, which the venv's own
interpreter does not load. Standard library only for the same reason.

Exit 0 done, 2 bad input (capture unreadable, resource / event / subresource not in it, a format
it cannot convert), 3 environment (no renderdoc module, replay unavailable); one line on stderr.
"""
import array
import json
import os
import struct
import sys

EXIT_BAD_INPUT, EXIT_ENVIRONMENT = 2, 3


class Failure(Exception):
    def __init__(self, code, message):
        super().__init__(message)
        self.code = code


def load_renderdoc():
    # Headless replay: Mesa's EGL picks X11 for the default display, which a machine without a
    # display server lacks ("Couldn't open default EGL display"); its surfaceless platform needs
    # none and replays OpenGL captures on llvmpipe (docs/external_format.md).
    if not os.environ.get("DISPLAY") and not os.environ.get("WAYLAND_DISPLAY"):
        os.environ.setdefault("EGL_PLATFORM", "surfaceless")
    try:
        import renderdoc
    except ImportError as e:
        raise Failure(EXIT_ENVIRONMENT, f"no renderdoc Python module ({e}; Debian: apt-get install python3-renderdoc)")
    return renderdoc


def open_capture(rd, path):
    rd.InitialiseReplay(rd.GlobalEnvironment(), [])
    cap = rd.OpenCaptureFile()
    try:
        result = cap.OpenFile(path, "", None)
        if result != rd.ResultCode.Succeeded:
            raise Failure(EXIT_BAD_INPUT, f"{path}: not a readable RenderDoc capture ({result.Message()})")
        if cap.LocalReplaySupport() != rd.ReplaySupport.Supported:
            raise Failure(EXIT_ENVIRONMENT, f"{path}: this machine cannot replay a {cap.DriverName()} capture")
        result, controller = cap.OpenCapture(rd.ReplayOptions(), None)
        if result != rd.ResultCode.Succeeded:
            raise Failure(EXIT_ENVIRONMENT, f"{path}: replay failed ({result.Message()})")
        return cap, controller
    except Failure:
        # Shut RenderDoc down before the interpreter's teardown does: a refused capture left both
        # open, and once under a loaded test run (ctest -j2 beside a campaign) the process then
        # aborted after its message (exit 134, reported as an environment error instead of exit 2).
        cap.Shutdown()
        rd.ShutdownReplay()
        raise


def resource_id(rd, controller, wanted):
    """A debug label (exactly one resource of that name), 'ResourceId::N' or the digits N."""
    ids = {str(r.resourceId): r.resourceId for r in controller.GetResources()}
    key = wanted if wanted.startswith("ResourceId::") else "ResourceId::" + wanted
    if wanted.isdigit() or wanted.startswith("ResourceId::"):
        if key in ids:
            return ids[key]
    named = [r.resourceId for r in controller.GetResources() if r.name == wanted]
    if len(named) > 1:
        raise Failure(EXIT_BAD_INPUT, f"resource '{wanted}': {len(named)} resources have this label; name one by id")
    if not named:
        raise Failure(EXIT_BAD_INPUT, f"resource '{wanted}': no resource of that label or id in the capture")
    return named[0]


def last_event(action):
    children = list(action.children)
    return max([action.eventId] + [last_event(c) for c in children])


def find_action(actions, name, names_of):
    for a in actions:
        if name in names_of(a):
            return a
        found = find_action(list(a.children), name, names_of)
        if found is not None:
            return found
    return None


def event_id(controller, event):
    roots = list(controller.GetRootActions())
    if not roots:
        raise Failure(EXIT_BAD_INPUT, "the capture holds no events")
    if event == "end":
        return last_event(roots[-1])
    if event.isdigit():
        return int(event)
    sf = controller.GetStructuredFile()
    action = find_action(roots, event, lambda a: (a.customName, a.GetName(sf)))
    if action is None:
        raise Failure(EXIT_BAD_INPUT, f"event '{event}': no debug group or action of that name in the capture")
    return last_event(action)


def scalar_reader(rd, fmt):
    """(struct code, scale) of one component of a regular format: value = raw * scale."""
    width, kind = fmt.compByteWidth, fmt.compType
    if kind in (rd.CompType.Float, rd.CompType.Depth) and width in (2, 4) and not (kind == rd.CompType.Depth and width == 2):
        return ("e" if width == 2 else "f"), 1.0
    unsigned = {1: "B", 2: "H", 4: "I"}
    signed = {1: "b", 2: "h", 4: "i"}
    if kind in (rd.CompType.UNorm, rd.CompType.UNormSRGB, rd.CompType.Depth) and width in unsigned:
        return unsigned[width], 1.0 / float((1 << (8 * width)) - 1)
    if kind == rd.CompType.UInt and width in unsigned:
        return unsigned[width], 1.0
    if kind == rd.CompType.SInt and width in signed:
        return signed[width], 1.0
    return None, None


def to_floats(rd, fmt, data, texels):
    """The texture's bytes as floats, texels * channels, and the channel count."""
    if fmt.type == rd.ResourceFormatType.D32S8:  # float depth, 8-bit stencil, 24 bits padding
        return array.array("f", struct.unpack_from(f"<{texels * 2}f", data)[0::2]), 1
    if fmt.type == rd.ResourceFormatType.D24S8:  # GL packs depth in the high 24 bits (GL 4.5 §8.4.4.2)
        return array.array("f", [(v >> 8) / 16777215.0 for v in struct.unpack_from(f"<{texels}I", data)]), 1
    if fmt.type != rd.ResourceFormatType.Regular:
        raise Failure(EXIT_BAD_INPUT, f"format {fmt.Name()} is not one vct import-capture converts")
    code, scale = scalar_reader(rd, fmt)
    if code is None:
        raise Failure(EXIT_BAD_INPUT, f"format {fmt.Name()} is not one vct import-capture converts")
    n = texels * fmt.compCount
    if code == "f":  # float32 as stored: no per-value work (a 256^3 RGBA volume is 67 M values)
        out = array.array("f")
        out.frombytes(data[: n * 4])
    else:
        values = struct.unpack_from(f"<{n}{code}", data)
        out = array.array("f", [float(v) * scale for v in values])
    if fmt.BGRAOrder() and fmt.compCount >= 3:
        for i in range(0, n, fmt.compCount):
            out[i], out[i + 2] = out[i + 2], out[i]
    return out, fmt.compCount


def texture_of(controller, rid):
    for t in controller.GetTextures():
        if t.resourceId == rid:
            return t
    raise Failure(EXIT_BAD_INPUT, f"{rid} is not a texture")


def read_stage(rd, controller, stage):
    where = f"stage '{stage['name']}'"
    try:
        rid = resource_id(rd, controller, stage["resource"])
        tex = texture_of(controller, rid)
        eid = event_id(controller, stage["event"])
    except Failure as f:
        raise Failure(f.code, f"{where}: {f}")
    mip, layer, sample = stage["mip"], stage["slice"], stage["sample"]
    if mip >= tex.mips or (tex.depth == 1 and layer >= tex.arraysize) or sample >= max(1, tex.msSamp):
        raise Failure(EXIT_BAD_INPUT, f"{where}: '{stage['resource']}' has {tex.mips} levels, {tex.arraysize} layers, "
                                      f"{tex.msSamp} samples; asked level {mip}, layer {layer}, sample {sample}")
    controller.SetFrameEvent(eid, False)  # replayed only when the event differs from the last
    w, h = max(1, tex.width >> mip), max(1, tex.height >> mip)
    d = max(1, tex.depth >> mip) if tex.depth > 1 else 1
    data = bytes(controller.GetTextureData(rid, rd.Subresource(mip, layer if d == 1 else 0, sample)))
    values, channels = to_floats(rd, tex.format, data, w * h * d)
    return {"width": w, "height": h, "depth": d, "channels": channels, "format": tex.format.Name(), "event": eid}, values


def main(argv):
    if len(argv) != 4:
        raise Failure(EXIT_BAD_INPUT, "usage: rdc_read.py CAPTURE.rdc REQUEST.json OUTDIR")
    capture, request, outdir = argv[1:]
    with open(request) as f:
        stages = json.load(f)["stages"]
    rd = load_renderdoc()
    cap, controller = open_capture(rd, capture)
    try:
        index = []
        for i, stage in enumerate(stages):
            entry, values = read_stage(rd, controller, stage)
            with open(os.path.join(outdir, f"{i}.f32"), "wb") as f:
                values.tofile(f)
            index.append(entry)
        with open(os.path.join(outdir, "index.json"), "w") as f:
            json.dump(index, f)
    finally:
        controller.Shutdown()
        cap.Shutdown()
        rd.ShutdownReplay()


if __name__ == "__main__":
    try:
        main(sys.argv)
    except Failure as failure:
        print(f"rdc_read: {failure}", file=sys.stderr)
        sys.exit(failure.code)
