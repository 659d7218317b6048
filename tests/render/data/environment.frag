#version 400
// Irradiance and mirror radiance from MaterialX's lat-long maps, looked up the way MaterialX's
// mx_latlong_map_lookup does (direction through u_envMatrix, v = 0 at +Y).
uniform mat4 u_envMatrix = mat4(1.0);
uniform sampler2D u_envRadiance;
uniform sampler2D u_envIrradiance;
uniform int u_envRadianceMips = 1;
uniform float u_envLightIntensity = 0.0;
uniform vec3 u_viewPosition = vec3(0.0);
uniform int u_mirror = 0;  // 0: irradiance along the normal, 1: radiance along the reflection

in VertexData
{
    vec3 normalWorld;
    vec3 positionWorld;
    vec2 texcoord_0;
} vd;

out vec4 out1;

vec2 latlong(vec3 dir)
{
    vec3 d = normalize((u_envMatrix * vec4(dir, 0.0)).xyz);
    float latitude = -asin(d.y) / 3.14159265358979 + 0.5;
    float longitude = atan(d.x, -d.z) / 3.14159265358979 * 0.5 + 0.5;
    return vec2(longitude, latitude);
}

void main()
{
    vec3 N = normalize(vd.normalWorld);
    vec3 V = normalize(u_viewPosition - vd.positionWorld);
    vec3 colour = u_mirror == 1 ? textureLod(u_envRadiance, latlong(reflect(-V, N)), 0.0).rgb
                                : textureLod(u_envIrradiance, latlong(N), 0.0).rgb;
    out1 = vec4(colour * u_envLightIntensity, 1.0);
}
