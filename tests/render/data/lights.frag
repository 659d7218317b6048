#version 400
// Direct lighting the way MaterialX's generated code dispatches on LightData.type: type 1 is the
// rig's first light category (directional_light here), type 2 the second (point_light).
#define MAX_LIGHT_SOURCES 3

struct LightData
{
    int type;
    vec3 direction;
    vec3 position;
    vec3 color;
    float intensity;
};

uniform LightData u_lightData[MAX_LIGHT_SOURCES];
uniform int u_numActiveLightSources = 0;

in VertexData
{
    vec3 normalWorld;
    vec3 positionWorld;
    vec2 texcoord_0;
} vd;

out vec4 out1;

void main()
{
    vec3 N = normalize(vd.normalWorld);
    vec3 radiance = vec3(0.0);
    for (int i = 0; i < min(u_numActiveLightSources, MAX_LIGHT_SOURCES); ++i)
    {
        LightData light = u_lightData[i];
        if (light.type == 1)
            radiance += max(dot(N, -light.direction), 0.0) * light.color * light.intensity;
        else if (light.type == 2)
            radiance += light.color * light.intensity;  // unshadowed ambient stand-in: position unused
    }
    out1 = vec4(radiance, 1.0);
}
