// <point_light>: light from `light.position`, falling off as (distance + 1)^-decay_rate.
void mx_point_light(LightData light, vec3 position, out lightshader result)
{
    vec3 toLight = light.position - position;
    float dist = length(toLight) + 1.0e-8;
    result.direction = toLight / dist;
    result.intensity = light.color * light.intensity / pow(dist + 1.0, light.decay_rate + 1.0e-8);
}
