// <surface_unlit>: emits emission * emission_color and transmits transmission * transmission_color;
// opacity fades both toward a fully transparent surface.
void mx_surface_unlit(float emission, vec3 emission_color, float transmission, vec3 transmission_color, float opacity, out surfaceshader result)
{
    result.color = emission * emission_color * opacity;
    result.transparency = mix(vec3(1.0), transmission * transmission_color, opacity);
}
