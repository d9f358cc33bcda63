"""The pipelines' Cook–Torrance BRDF (ref/shared/vct_shared.h: cook_torrance, surface_pbr) as a
Mitsuba 3 BSDF plugin written in Python, so that Mitsuba's own path integrator, emitter sampling
and MIS check our path tracer on glossy surfaces (issue 16; bench/mitsuba_compare.py --glossy,
bound in docs/compare.md "Path tracer against Mitsuba 3").

Only the BRDF *value* is shared (it is the definition both renderers must integrate); where to
sample is Mitsuba's: a mixture of its cosine-hemisphere warp and its GGX visible-normal sampler
(mi.MicrofacetDistribution), not ref/pt/bsdf_sampling.cpp. Two-sided as our path tracer shades
(ref/pt/integrator.cpp orient_normals: the normal is turned toward the viewer).

Import it after mi.set_variant (its class derives from the variant's mi.BSDF).

Parameters (floats): albedo_r, albedo_g, albedo_b, metallic, roughness, specular_factor.
The KHR_materials_specular colour is taken as white (the scenes this is used on do not set it).
"""
import math

import mitsuba as mi

MIN_ROUGHNESS = 0.03  # vct_shared.h MIN_ROUGHNESS


def _lerp(a, b, t):
    return a + (b - a) * t


class SurfacePbr:
    """vct_shared.h surface_pbr, in Python floats."""

    def __init__(self, albedo, metallic, roughness, specular_factor):
        self.albedo = albedo
        self.metallic = min(max(metallic, 0.0), 1.0)
        self.roughness = min(max(roughness, MIN_ROUGHNESS), 1.0)
        dielectric_f0 = min(0.04, 1.0) * specular_factor
        self.f0 = [_lerp(dielectric_f0, a, self.metallic) for a in albedo]
        self.f90 = _lerp(specular_factor, 1.0, self.metallic)


def ggx_distribution(n_dot_h, sin2, roughness):
    """vct_shared.h ggx_distribution, from cos and sin² of the half vector's angle."""
    a2 = roughness ** 4
    c2, s2 = (n_dot_h * n_dot_h, sin2) if n_dot_h > 0.0 else (0.0, 1.0)
    d = c2 * a2 + s2
    return a2 / max(math.pi * d * d, 1e-12)


def schlick_ggx_g1(n_dot_x, roughness):
    k = (roughness + 1.0) ** 2 / 8.0
    return n_dot_x / (n_dot_x * (1.0 - k) + k)


def cook_torrance(s, v, l):
    """f(l, v) per channel, local frame (z = normal), v and l pointing away from the surface."""
    if l[2] <= 0.0 or v[2] <= 0.0:
        return [0.0, 0.0, 0.0]
    h = [v[i] + l[i] for i in range(3)]
    norm = math.sqrt(sum(c * c for c in h))
    h = [c / norm for c in h]
    m5 = min(max(1.0 - max(sum(h[i] * v[i] for i in range(3)), 0.0), 0.0), 1.0) ** 5
    fresnel = [f0 + (s.f90 - f0) * m5 for f0 in s.f0]
    d = ggx_distribution(h[2], h[0] * h[0] + h[1] * h[1], s.roughness)
    g = schlick_ggx_g1(l[2], s.roughness) * schlick_ggx_g1(v[2], s.roughness)
    spec = d * g / (4.0 * l[2] * v[2])
    return [fresnel[i] * spec + (1.0 - fresnel[i]) * (1.0 - s.metallic) * s.albedo[i] / math.pi for i in range(3)]


class VctCookTorrance(mi.BSDF):
    def __init__(self, props):
        mi.BSDF.__init__(self, props)
        albedo = [props.get("albedo_r", 0.5), props.get("albedo_g", 0.5), props.get("albedo_b", 0.5)]
        self.surface = SurfacePbr(albedo, props.get("metallic", 0.0), props.get("roughness", 1.0),
                                  props.get("specular_factor", 1.0))
        # Metals have no diffuse lobe (kd = 0): all samples go to the specular one.
        self.p_specular = 1.0 if self.surface.metallic >= 1.0 else 0.5
        self.distribution = mi.MicrofacetDistribution(mi.MicrofacetType.GGX, self.surface.roughness ** 2, True)
        flags = (mi.BSDFFlags.GlossyReflection | mi.BSDFFlags.DiffuseReflection | mi.BSDFFlags.FrontSide
                 | mi.BSDFFlags.BackSide)
        self.m_components = [flags]
        self.m_flags = flags

    @staticmethod
    def _upper(wi, wo):
        """Both directions turned to the side wi is on (two-sided shading)."""
        sign = 1.0 if wi[2] >= 0.0 else -1.0
        return [wi[0], wi[1], wi[2] * sign], [wo[0], wo[1], wo[2] * sign]

    def _pdf(self, v, l):
        if l[2] <= 0.0 or v[2] <= 0.0:
            return 0.0
        pdf = (1.0 - self.p_specular) * l[2] / math.pi
        h = mi.ScalarVector3f(v[0] + l[0], v[1] + l[1], v[2] + l[2])
        h = h / math.sqrt(h[0] ** 2 + h[1] ** 2 + h[2] ** 2)
        l_dot_h = l[0] * h[0] + l[1] * h[1] + l[2] * h[2]
        if self.p_specular > 0.0 and l_dot_h > 0.0:
            pdf += self.p_specular * self.distribution.pdf(mi.Vector3f(v), mi.Vector3f(h)) / (4.0 * l_dot_h)
        return pdf

    def _value(self, v, l):
        f = cook_torrance(self.surface, v, l)
        return mi.Color3f(f[0] * l[2], f[1] * l[2], f[2] * l[2])  # Mitsuba's eval includes cos(wo)

    def sample(self, ctx, si, sample1, sample2, active=True):
        v, _ = self._upper(si.wi, si.wi)
        if sample1 < self.p_specular:
            m, _ = self.distribution.sample(mi.Vector3f(v), sample2)
            v_dot_m = v[0] * m[0] + v[1] * m[1] + v[2] * m[2]
            l = [2.0 * v_dot_m * m[i] - v[i] for i in range(3)]
        else:
            w = mi.warp.square_to_cosine_hemisphere(sample2)
            l = [w[0], w[1], w[2]]
        bs = mi.BSDFSample3f()
        pdf = self._pdf(v, l)
        if pdf <= 0.0:
            return bs, mi.Color3f(0.0)
        sign = 1.0 if si.wi[2] >= 0.0 else -1.0
        bs.wo = mi.Vector3f(l[0], l[1], l[2] * sign)
        bs.pdf = pdf
        bs.eta = 1.0
        bs.sampled_type = int(mi.BSDFFlags.GlossyReflection)
        bs.sampled_component = 0
        return bs, self._value(v, l) / pdf

    def eval(self, ctx, si, wo, active=True):
        v, l = self._upper(si.wi, wo)
        return self._value(v, l)

    def pdf(self, ctx, si, wo, active=True):
        v, l = self._upper(si.wi, wo)
        return self._pdf(v, l)

    def eval_pdf(self, ctx, si, wo, active=True):
        v, l = self._upper(si.wi, wo)
        return self._value(v, l), self._pdf(v, l)

    def traverse(self, callback):
        pass

    def to_string(self):
        return "VctCookTorrance[metallic=%g, roughness=%g]" % (self.surface.metallic, self.surface.roughness)


def register():
    """Makes {"type": "vct_cook_torrance", ...} loadable (call after mi.set_variant)."""
    mi.register_bsdf("vct_cook_torrance", lambda props: VctCookTorrance(props))
