struct VertexUniforms {
    u_worldMatrix: mat4x4f,  // offset 0
    u_viewProjectionMatrix: mat4x4f,  // offset 64
    u_worldInverseTransposeMatrix: mat4x4f,  // offset 128
}
@group(0) @binding(0) var<uniform> vu: VertexUniforms;

struct AppData {
    @location(0) i_position: vec3f,
    @location(1) i_normal: vec3f,
    @location(2) i_tangent: vec3f,
}

struct VertexData {
    @builtin(position) position: vec4f,
    @location(0) normalWorld: vec3f,
    @location(1) tangentWorld: vec3f,
    @location(2) positionWorld: vec3f,
}

@vertex
fn vertexMain(vin: AppData) -> VertexData {
    var vd: VertexData;
    var hPositionWorld: vec4f = vu.u_worldMatrix * vec4f(vin.i_position, 1.0);
    vd.position = vu.u_viewProjectionMatrix * hPositionWorld;
    vd.normalWorld = normalize((vu.u_worldInverseTransposeMatrix * vec4f(vin.i_normal, 0.0)).xyz);
    vd.tangentWorld = normalize((vu.u_worldMatrix * vec4f(vin.i_tangent, 0.0)).xyz);
    vd.positionWorld = hPositionWorld.xyz;
    return vd;
}
