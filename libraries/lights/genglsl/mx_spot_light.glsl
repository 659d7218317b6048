// <spot_light>: a point light restricted to a cone about `light.direction`. As in MaterialX's
// hardware lights, inner_angle and outer_angle are compared with the cosine between the cone axis
// and the direction to the shaded point: full intensity where that cosine is at least inner_angle,
// none below min(inner_angle, outer_angle), smooth in between.
void mx_spot_light(LightData light, vec3 position, out lightshader result)
{
    vec3 toLight = light.position - position;
    float dist = length(toLight) + 1.0e-8;
    result.direction = toLight / dist;
    result.intensity = light.color * light.intensity / pow(dist + 1.0, light.decay_rate + 1.0e-8);

    float cosAxis = dot(result.direction, -light.direction);
    float low = min(light.inner_angle, light.outer_angle);
    float high = light.inner_angle;
    result.intensity *= (low < high) ? smoothstep(low, high, cosAxis) : step(high, cosAxis);
}
