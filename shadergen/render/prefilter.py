"""The GGX-prefiltered radiance chain that mx_environment_prefilter.glsl reads as u_envRadiance.

Level 0 is the unfiltered lat-long map; level l >= 1 holds the map convolved with the GGX lobe of
alpha = 2^(l - roughest) (roughest = mips - 4, at least 1), alpha 1 from there on: each level's
texels are about as wide as its lobe. The convolution assumes N = V = R (Karis 2013, "Real Shading
in Unreal Engine 4") and weights each reflected direction by its cosine; it is computed on the GPU
when an environment is first used, by filtered importance sampling (Krivanek & Colbert 2008) of the
radiance map's own mip chain, with GGX normals drawn from a spherical Fibonacci set.
"""
import numpy as np

from .textures import Sampling, bind, upload

SAMPLES = 512  # GGX normals per texel of each level

_VERTEX = """
#version 400
void main()
{
    // one triangle that covers the viewport
    vec2 corner = vec2(float((gl_VertexID & 1) << 2), float((gl_VertexID & 2) << 1)) - 1.0;
    gl_Position = vec4(corner, 0.0, 1.0);
}
"""

_FRAGMENT = """
#version 400
uniform sampler2D u_source;      // the mipmapped lat-long radiance
uniform float u_sourceRows;      // rows of its level 0
uniform vec2 u_size;             // columns, rows of the level being written
uniform float u_alpha;
uniform int u_samples;
out vec3 colour;

const float PI = 3.14159265358979;

vec3 map_direction(vec2 uv)
{
    float lat = (0.5 - uv.y) * PI, lon = (uv.x - 0.5) * 2.0 * PI;
    return vec3(cos(lat) * sin(lon), sin(lat), -cos(lat) * cos(lon));
}

vec2 map_uv(vec3 d)
{
    return vec2(atan(d.x, -d.z) / (2.0 * PI) + 0.5, 0.5 - asin(clamp(d.y, -1.0, 1.0)) / PI);
}

void main()
{
    vec3 N = map_direction(gl_FragCoord.xy / u_size);
    vec3 up = abs(N.y) < 0.999 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    vec3 T = normalize(cross(up, N));
    vec3 B = cross(N, T);
    float a2 = u_alpha * u_alpha;
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    for (int i = 0; i < u_samples; i++)
    {
        // spherical Fibonacci point -> GGX normal (inverse CDF of D cos(theta_h))
        float u1 = (float(i) + 0.5) / float(u_samples);
        float phi = 2.0 * PI * fract(float(i) * 0.6180339887498949);
        float cosH = sqrt((1.0 - u1) / (1.0 + (a2 - 1.0) * u1));
        float sinH = sqrt(max(1.0 - cosH * cosH, 0.0));
        vec3 H = T * (sinH * cos(phi)) + B * (sinH * sin(phi)) + N * cosH;
        vec3 L = 2.0 * cosH * H - N;
        float NdotL = dot(N, L);
        if (NdotL <= 0.0)
            continue;
        // density of L: D(H) cos(theta_h) / (4 VdotH) = D(H) / 4 with V = N
        float d = cosH * cosH * (a2 - 1.0) + 1.0;
        float pdf = a2 / (PI * d * d) / 4.0;
        // mip whose texel covers 1 / (samples pdf); a level-0 texel spans (pi / rows)^2 cos(lat)
        float stretch = max(sqrt(1.0 - L.y * L.y), 1e-4);
        float lod = 0.5 * log2(1.0 / (float(u_samples) * pdf * stretch)) + log2(u_sourceRows / PI) + 1.0;
        sum += textureLod(u_source, map_uv(L), max(lod, 0.0)).rgb * NdotL;
        weight += NdotL;
    }
    colour = sum / max(weight, 1e-8);
}
"""


def level_alphas(mips: int) -> list[float]:
    """GGX alpha of each level of the chain (0 for the unfiltered level 0); what
    mx_prefiltered_lod() inverts."""
    roughest = max(mips - 4, 1)
    return [0.0] + [min(1.0, 2.0 ** (level - roughest)) for level in range(1, mips)]


def prefiltered_chain(ctx, radiance: np.ndarray, source, sampling: Sampling, samples: int = SAMPLES):
    """A mipmapped texture of the chain, from the (h, w, 3) lat-long `radiance` and `source`, its
    uploaded mipmapped texture, read with `sampling`."""
    import moderngl

    rows, columns = radiance.shape[:2]
    levels = []
    mips = int(np.floor(np.log2(max(rows, columns)))) + 1
    program = ctx.program(vertex_shader=_VERTEX, fragment_shader=_FRAGMENT)
    vao = ctx.vertex_array(program, [])
    bind(source, 0, sampling)
    program["u_source"].value = 0
    program["u_sourceRows"].value = float(rows)
    program["u_samples"].value = samples
    try:
        for level, alpha in enumerate(level_alphas(mips)):
            if level == 0:
                continue
            size = (max(columns >> level, 1), max(rows >> level, 1))
            target = ctx.texture(size, 3, dtype="f4")
            framebuffer = ctx.framebuffer(color_attachments=[target])
            framebuffer.use()
            program["u_size"].value = (float(size[0]), float(size[1]))
            program["u_alpha"].value = alpha
            vao.render(moderngl.TRIANGLES, vertices=3)
            levels.append(np.frombuffer(framebuffer.read(components=3, dtype="f4"), "f4").reshape(size[1], size[0], 3))
            framebuffer.release()
            target.release()
    finally:
        vao.release()
        program.release()
    return upload(ctx, radiance, levels)
