#include "lib/mx_texture.glsl"

// <latlongimage>: look up a lat-long (equirectangular) environment image in direction `viewdir`.
// Longitude -atan2(x, z) maps to u in [0, 1) with the -z direction at 0 and +z at 0.5, shifted by
// `rotation` degrees; latitude asin(y) maps to v. u repeats, v mirrors, filtering is linear.
void mx_latlongimage(sampler2D file, vec3 dflt, vec3 viewdir, float rotation, out vec3 result)
{
    const float INV_TWO_PI = 0.15915494309189535;
    const float INV_PI = 0.3183098861837907;
    vec2 uv = vec2(0.5 - atan(viewdir.x, viewdir.z) * INV_TWO_PI + rotation / 360.0,
                   0.5 + asin(viewdir.y) * INV_PI);
    result = mx_image_fetch(file, vec4(dflt, 0.0), vec2(uv.x, 1.0 - uv.y), 2, 3, 1).rgb;
}
