// <heighttonormal>: the tangent-space normal of a height field, from screen-space derivatives.
//
// With J the Jacobian of the texture coordinate over the screen, the height's texture-space
// gradient g satisfies (dh/dx, dh/dy) = g * J. The unnormalised normal (-g, 1) scaled by det(J) is
// the cross product of the screen-space frame vectors (du/dx, dv/dx, dh/dx) x (du/dy, dv/dy, dh/dy),
// which needs no division and stays finite where J is singular. The 1/16 factor gives the slope a
// Sobel filter over one-texel offsets would report, which is what `scale` = 1 is calibrated to.
void mx_heighttonormal_vector3(float height, float scale, vec2 texcoord, out vec3 result)
{
    float slope = scale / 16.0;
    vec3 along_x = vec3(dFdx(texcoord), dFdx(height) * slope);
    vec3 along_y = vec3(dFdy(texcoord), dFdy(height) * slope);
    vec3 n = cross(along_x, along_y);
    n *= sign(n.z) == 0.0 ? 1.0 : sign(n.z);  // a mirrored texture mapping must not flip the normal inward
    float len = length(n);
    result = len > 0.0 ? (n / len) * 0.5 + 0.5 : vec3(0.5, 0.5, 1.0);
}
