// Reading the albedo tables that tools/fit_albedo.py writes: regular grids over [0, 1]^2 with a
// node at both ends, interpolated bilinearly.

// The cell of a grid of `size` (columns, rows) nodes that holds point p (clamped to the grid):
// xy its lower node, zw the interpolation weights along each axis.
vec4 mx_albedo_cell(vec2 p, vec2 size)
{
    vec2 x = clamp(p, 0.0, 1.0) * (size - 1.0);
    vec2 i = min(floor(x), size - 2.0);
    return vec4(i, x - i);
}

int mx_albedo_index(ivec2 node, int columns)
{
    return node.y * columns + node.x;
}
