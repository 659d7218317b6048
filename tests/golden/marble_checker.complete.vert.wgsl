struct VertexUniforms {
    u_worldMatrix: mat4x4f,  // offset 0
    u_viewProjectionMatrix: mat4x4f,  // offset 64
}
@group(0) @binding(0) var<uniform> vu: VertexUniforms;

struct AppData {
    @location(0) i_position: vec3f,
    @location(1) i_texcoord_0: vec2f,
}

struct VertexData {
    @builtin(position) position: vec4f,
    @location(0) positionObject: vec3f,
    @location(1) texcoord_0: vec2f,
}

@vertex
fn vertexMain(vin: AppData) -> VertexData {
    var vd: VertexData;
    var hPositionWorld: vec4f = vu.u_worldMatrix * vec4f(vin.i_position, 1.0);
    vd.position = vu.u_viewProjectionMatrix * hPositionWorld;
    vd.positionObject = vin.i_position;
    vd.texcoord_0 = vin.i_texcoord_0;
    return vd;
}
