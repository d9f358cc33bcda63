"""Minimal inline SVG plots (no libraries): line plots with a log-or-linear y axis."""
import html
import math

COLORS = ["#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b"]


def line_plot(title, xs, series, xlabel="", ylabel="", logy=False, w=420, h=240):
    """series: list of (name, [y...]) aligned with xs (x may be strings: categorical)."""
    pts = [y for _, ys in series for y in ys if y is not None and (not logy or y > 0)]
    if not xs or not pts:
        return '<div class="missing">%s: no data</div>' % html.escape(title)
    f = (lambda v: math.log10(v)) if logy else (lambda v: v)
    lo, hi = min(f(v) for v in pts), max(f(v) for v in pts)
    if hi - lo < 1e-12:
        lo, hi = lo - 0.5, hi + 0.5
    L, R, T, B = 60, 110, 24, 36
    def X(i):
        return L + (w - L - R) * (i / max(1, len(xs) - 1))
    def Y(v):
        return T + (h - T - B) * (1 - (f(v) - lo) / (hi - lo))
    out = ['<svg width="%d" height="%d" xmlns="http://www.w3.org/2000/svg" style="background:#fff;border:1px solid #ddd">' % (w, h),
           '<text x="%d" y="15" font-weight="bold">%s</text>' % (L, html.escape(title))]
    out.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="#888"/>' % (L, h - B, w - R, h - B))
    out.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="#888"/>' % (L, T, L, h - B))
    for i, x in enumerate(xs):
        out.append('<text x="%.1f" y="%d" text-anchor="middle">%s</text>' % (X(i), h - B + 14, html.escape(str(x))))
    # Enough significant digits that neighbouring ticks differ (a narrow range around a large
    # value, e.g. a converged energy curve, would otherwise print five equal labels).
    span = (10 ** hi - 10 ** lo) if logy else (hi - lo)
    top = max(abs(10 ** lo if logy else lo), abs(10 ** hi if logy else hi), 1e-300)
    digits = max(3, min(10, int(math.ceil(math.log10(top / max(span / 4, 1e-300)))) + 1))
    for t in range(5):
        fv = lo + (hi - lo) * t / 4
        v = 10 ** fv if logy else fv
        y = T + (h - T - B) * (1 - t / 4)
        out.append('<text x="%d" y="%.1f" text-anchor="end">%.*g</text>' % (L - 4, y + 4, digits, v))
        out.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="#eee"/>' % (L, y, w - R, y))
    for k, (name, ys) in enumerate(series):
        c = COLORS[k % len(COLORS)]
        p = [(X(i), Y(y)) for i, y in enumerate(ys) if y is not None and (not logy or y > 0)]
        if p:
            out.append('<polyline fill="none" stroke="%s" stroke-width="2" points="%s"/>' % (c, " ".join("%.1f,%.1f" % q for q in p)))
            out.extend('<circle cx="%.1f" cy="%.1f" r="3" fill="%s"/>' % (q[0], q[1], c) for q in p)
        out.append('<text x="%d" y="%d" fill="%s">%s</text>' % (w - R + 6, T + 14 * k + 8, c, html.escape(name)))
    out.append('<text x="%d" y="%d" text-anchor="middle">%s</text>' % ((L + w - R) // 2, h - 4, html.escape(xlabel)))
    out.append('<text x="12" y="%d" transform="rotate(-90 12 %d)" text-anchor="middle">%s</text>' % (h // 2, h // 2, html.escape(ylabel + (" (log)" if logy else ""))))
    out.append("</svg>")
    return "".join(out)
