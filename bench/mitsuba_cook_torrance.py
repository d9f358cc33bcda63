"""The pipelines' Cook–Torrance BRDF (ref/shared/vct_shared.h: cook_torrance, surface_pbr) as a
Mitsuba 3 BSDF plugin written in Python, so that Mitsuba's own path integrator, emitter sampling
and MIS check our path tracer on glossy surfaces (issue 16; bench/mitsuba_compare.py --glossy,
bound in docs/compare.md "Path tracer against Mitsuba 3").

Only the BRDF *value* is shared (it is the definition both renderers must integrate); where to
sample is Mitsuba's: a mixture of its cosine-hemisphere warp and its GGX visible-normal sampler
(mi.MicrofacetDistribution), not ref/pt/bsdf_sampling.cpp. Two-sided as our path tracer shades
(ref/pt/integrator.cpp orient_normals: the normal is turned toward the viewer).

Import it after mi.set_variant (its class derives from the variant's mi.BSDF); it runs on scalar
and vectorised (llvm_ad_rgb) variants alike.

Parameters (floats): albedo_r, albedo_g, albedo_b, metallic, roughness, specular_factor.
The KHR_materials_specular colour is taken as white (the scenes this is used on do not set it).
"""
import math

import drjit as dr
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
    up = n_dot_h > 0.0
    c2, s2 = dr.select(up, n_dot_h * n_dot_h, 0.0), dr.select(up, sin2, 1.0)
    d = c2 * a2 + s2
    return a2 / dr.maximum(math.pi * d * d, 1e-12)


def schlick_ggx_g1(n_dot_x, roughness):
    k = (roughness + 1.0) ** 2 / 8.0
    return n_dot_x / (n_dot_x * (1.0 - k) + k)


def cook_torrance(s, v, l):
    """f(l, v) per channel (mi.Color3f), local frame (z = normal), v and l pointing away from the
    surface; written with Dr.Jit selects so that one definition runs per ray (scalar variants)
    and per wavefront (llvm_ad_rgb)."""
    active = (l.z > 0.0) & (v.z > 0.0)
    h = dr.normalize(v + l)
    m5 = dr.clip(1.0 - dr.maximum(dr.dot(h, v), 0.0), 0.0, 1.0) ** 5
    fresnel = mi.Color3f(s.f0) + (s.f90 - mi.Color3f(s.f0)) * m5
    d = ggx_distribution(h.z, h.x * h.x + h.y * h.y, s.roughness)
    g = schlick_ggx_g1(l.z, s.roughness) * schlick_ggx_g1(v.z, s.roughness)
    spec = d * g / dr.select(active, 4.0 * l.z * v.z, 1.0)
    f = fresnel * spec + (1.0 - fresnel) * ((1.0 - s.metallic) / math.pi) * mi.Color3f(s.albedo)
    return dr.select(active, f, 0.0)


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
    def _sign(wi):
        """+1 or -1: both directions are turned to the side wi is on (two-sided shading)."""
        return dr.select(wi.z >= 0.0, 1.0, -1.0)

    def _pdf(self, v, l):
        active = (l.z > 0.0) & (v.z > 0.0)
        pdf = (1.0 - self.p_specular) * l.z / math.pi
        if self.p_specular > 0.0:
            h = dr.normalize(v + l)
            l_dot_h = dr.dot(l, h)
            spec = self.p_specular * self.distribution.pdf(v, h) / dr.select(l_dot_h > 0.0, 4.0 * l_dot_h, 1.0)
            pdf = pdf + dr.select(l_dot_h > 0.0, spec, 0.0)
        return dr.select(active, pdf, 0.0)

    def _value(self, v, l):
        return cook_torrance(self.surface, v, l) * l.z  # Mitsuba's eval includes cos(wo)

    def sample(self, ctx, si, sample1, sample2, active=True):
        sign = self._sign(si.wi)
        v = mi.Vector3f(si.wi.x, si.wi.y, si.wi.z * sign)
        m, _ = self.distribution.sample(v, sample2)
        l = dr.select(sample1 < self.p_specular, 2.0 * dr.dot(v, m) * m - v,
                      mi.Vector3f(mi.warp.square_to_cosine_hemisphere(sample2)))
        pdf = self._pdf(v, l)
        valid = pdf > 0.0
        bs = dr.zeros(mi.BSDFSample3f)
        bs.wo = mi.Vector3f(l.x, l.y, l.z * sign)
        bs.pdf = dr.select(valid, pdf, 0.0)
        bs.eta = 1.0
        bs.sampled_type = mi.UInt32(int(mi.BSDFFlags.GlossyReflection))
        bs.sampled_component = mi.UInt32(0)
        return bs, dr.select(valid, self._value(v, l) / dr.select(valid, pdf, 1.0), 0.0)

    def _local(self, si, wo):
        sign = self._sign(si.wi)
        return mi.Vector3f(si.wi.x, si.wi.y, si.wi.z * sign), mi.Vector3f(wo.x, wo.y, wo.z * sign)

    def eval(self, ctx, si, wo, active=True):
        return self._value(*self._local(si, wo))

    def pdf(self, ctx, si, wo, active=True):
        return self._pdf(*self._local(si, wo))

    def eval_pdf(self, ctx, si, wo, active=True):
        v, l = self._local(si, wo)
        return self._value(v, l), self._pdf(v, l)

    def traverse(self, callback):
        pass

    def to_string(self):
        return "VctCookTorrance[metallic=%g, roughness=%g]" % (self.surface.metallic, self.surface.roughness)


def register():
    """Makes {"type": "vct_cook_torrance", ...} loadable (call after mi.set_variant)."""
    mi.register_bsdf("vct_cook_torrance", lambda props: VctCookTorrance(props))
