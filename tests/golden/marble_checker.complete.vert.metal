#include <metal_stdlib>
using namespace metal;

struct VertexUniforms
{
    float4x4 u_worldMatrix;  // offset 0
    float4x4 u_viewProjectionMatrix;  // offset 64
};

struct AppData
{
    float3 i_position [[attribute(0)]];
    float2 i_texcoord_0 [[attribute(1)]];
};

struct VertexData
{
    float4 position [[position]];
    float3 positionObject [[user(locn0)]];
    float2 texcoord_0 [[user(locn1)]];
};

vertex VertexData vertexMain(AppData vin [[stage_in]], constant VertexUniforms& vu [[buffer(0)]])
{
    VertexData vd;
    float4 hPositionWorld = vu.u_worldMatrix * float4(vin.i_position, 1.0);
    vd.position = vu.u_viewProjectionMatrix * hPositionWorld;
    vd.positionObject = vin.i_position;
    vd.texcoord_0 = vin.i_texcoord_0;
    return vd;
}
