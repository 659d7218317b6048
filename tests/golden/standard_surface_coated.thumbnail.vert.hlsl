cbuffer VertexUniforms
{
    row_major float4x4 u_worldMatrix;
    row_major float4x4 u_viewProjectionMatrix;
    row_major float4x4 u_worldInverseTransposeMatrix;
};

struct AppData
{
    float3 i_position : ATTRIBUTE0;
    float3 i_normal : ATTRIBUTE1;
    float3 i_tangent : ATTRIBUTE2;
};

struct VertexData
{
    float4 position : SV_Position;
    float3 normalWorld : TEXCOORD0;
    float3 tangentWorld : TEXCOORD1;
    float3 positionWorld : TEXCOORD2;
};

[shader("vertex")]
VertexData vertexMain(AppData vin)
{
    VertexData vd;
    float4 hPositionWorld = mul(float4(vin.i_position, 1.0), u_worldMatrix);
    vd.position = mul(hPositionWorld, u_viewProjectionMatrix);
    vd.normalWorld = normalize(mul(float4(vin.i_normal, 0.0), u_worldInverseTransposeMatrix).xyz);
    vd.tangentWorld = normalize(mul(float4(vin.i_tangent, 0.0), u_worldMatrix).xyz);
    vd.positionWorld = hPositionWorld.xyz;
    return vd;
}
