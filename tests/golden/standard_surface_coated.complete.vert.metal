#include <metal_stdlib>
using namespace metal;

struct VertexUniforms
{
    float4x4 u_worldMatrix;  // offset 0
    float4x4 u_viewProjectionMatrix;  // offset 64
    float4x4 u_worldInverseTransposeMatrix;  // offset 128
};

struct AppData
{
    float3 i_position [[attribute(0)]];
    float3 i_normal [[attribute(1)]];
    float3 i_tangent [[attribute(2)]];
};

struct VertexData
{
    float4 position [[position]];
    float3 normalWorld [[user(locn0)]];
    float3 tangentWorld [[user(locn1)]];
    float3 positionWorld [[user(locn2)]];
};

vertex VertexData vertexMain(AppData vin [[stage_in]], constant VertexUniforms& vu [[buffer(0)]])
{
    VertexData vd;
    float4 hPositionWorld = vu.u_worldMatrix * float4(vin.i_position, 1.0);
    vd.position = vu.u_viewProjectionMatrix * hPositionWorld;
    vd.normalWorld = normalize((vu.u_worldInverseTransposeMatrix * float4(vin.i_normal, 0.0)).xyz);
    vd.tangentWorld = normalize((vu.u_worldMatrix * float4(vin.i_tangent, 0.0)).xyz);
    vd.positionWorld = hPositionWorld.xyz;
    return vd;
}
