cbuffer VertexUniforms
{
    row_major float4x4 u_worldMatrix;
    row_major float4x4 u_viewProjectionMatrix;
};

struct AppData
{
    float3 i_position : ATTRIBUTE0;
    float2 i_texcoord_0 : ATTRIBUTE1;
};

struct VertexData
{
    float4 position : SV_Position;
    float3 positionObject : TEXCOORD0;
    float2 texcoord_0 : TEXCOORD1;
};

[shader("vertex")]
VertexData vertexMain(AppData vin)
{
    VertexData vd;
    float4 hPositionWorld = mul(float4(vin.i_position, 1.0), u_worldMatrix);
    vd.position = mul(hPositionWorld, u_viewProjectionMatrix);
    vd.positionObject = vin.i_position;
    vd.texcoord_0 = vin.i_texcoord_0;
    return vd;
}
