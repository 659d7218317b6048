// <splitlr> and <splittb>: a two-value split at `center` along u (left/right) or v
// (bottom/top), with the edge antialiased over about one pixel using screen-space derivatives.

float mx_split_step(float edge, float x)
{
    float halfwidth = length(vec2(dFdx(x), dFdy(x))) * 0.70710678118654757;
    return smoothstep(edge - halfwidth, edge + halfwidth, x);
}

void mx_splitlr_float(float valuel, float valuer, float center, vec2 texcoord, out float result)
{
    result = mix(valuel, valuer, mx_split_step(center, texcoord.x));
}

void mx_splitlr_vector2(vec2 valuel, vec2 valuer, float center, vec2 texcoord, out vec2 result)
{
    result = mix(valuel, valuer, mx_split_step(center, texcoord.x));
}

void mx_splitlr_vector3(vec3 valuel, vec3 valuer, float center, vec2 texcoord, out vec3 result)
{
    result = mix(valuel, valuer, mx_split_step(center, texcoord.x));
}

void mx_splitlr_vector4(vec4 valuel, vec4 valuer, float center, vec2 texcoord, out vec4 result)
{
    result = mix(valuel, valuer, mx_split_step(center, texcoord.x));
}

void mx_splittb_float(float valuet, float valueb, float center, vec2 texcoord, out float result)
{
    result = mix(valueb, valuet, mx_split_step(center, texcoord.y));
}

void mx_splittb_vector2(vec2 valuet, vec2 valueb, float center, vec2 texcoord, out vec2 result)
{
    result = mix(valueb, valuet, mx_split_step(center, texcoord.y));
}

void mx_splittb_vector3(vec3 valuet, vec3 valueb, float center, vec2 texcoord, out vec3 result)
{
    result = mix(valueb, valuet, mx_split_step(center, texcoord.y));
}

void mx_splittb_vector4(vec4 valuet, vec4 valueb, float center, vec2 texcoord, out vec4 result)
{
    result = mix(valueb, valuet, mx_split_step(center, texcoord.y));
}
