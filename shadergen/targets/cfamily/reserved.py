"""Words HLSL, Slang and MSL reserve or predeclare: keywords, types, intrinsic functions. They join
targets/names.py's RESERVED (a document's name takes one spelling in every target), and library
code that spells one is respelled `<name>_` by the C-family printer, as WGSL's is."""

HLSL_WORDS = set("""
AppendStructuredBuffer BlendState Buffer ByteAddressBuffer CompileShader ComputeShader ConsumeStructuredBuffer
DepthStencilState DepthStencilView DomainShader GeometryShader Hullshader InputPatch LineStream OutputPatch
PixelShader PointStream RWBuffer RWByteAddressBuffer RWStructuredBuffer RWTexture1D RWTexture1DArray RWTexture2D
RWTexture2DArray RWTexture3D RasterizerState RenderTargetView SamplerComparisonState SamplerState StructuredBuffer
Texture1D Texture1DArray Texture2D Texture2DArray Texture2DMS Texture2DMSArray Texture3D TextureCube
TextureCubeArray TriangleStream VertexShader asm asm_fragment bool break case cbuffer centroid class column_major
compile compile_fragment const continue default discard do double dword else export extern false float for
fxgroup groupshared half if in inline inout int interface line lineadj linear matrix min10float min12int
min16float min16int min16uint namespace nointerpolation noperspective out packoffset pass pixelfragment point
precise register return row_major sample sampler sampler1D sampler2D sampler3D samplerCUBE shared snorm stateblock
stateblock_state static string struct switch tbuffer technique technique10 technique11 texture texture1D
texture2D texture3D textureCUBE triangle triangleadj true typedef uint uniform unorm unsigned vector vertexfragment
void volatile while
abort abs acos all AllMemoryBarrier any asdouble asfloat asin asint asuint atan atan2 ceil clamp clip cos cosh
countbits cross ddx ddx_coarse ddx_fine ddy ddy_coarse ddy_fine degrees determinant distance dot dst errorf
EvaluateAttributeAtCentroid EvaluateAttributeAtSample EvaluateAttributeSnapped exp exp2 f16tof32 f32tof16
faceforward firstbithigh firstbitlow floor fma fmod frac frexp fwidth isfinite isinf isnan ldexp length lerp lit
log log10 log2 mad max min modf msad4 mul noise normalize pow printf radians rcp reflect refract reversebits round
rsqrt saturate sign sin sincos sinh smoothstep sqrt step tan tanh transpose trunc select
""".split())
HLSL_WORDS |= {f"{s}{n}" for s in ("float", "int", "uint", "bool", "half", "double", "min16float", "min16int")
               for n in ("1", "2", "3", "4")}
HLSL_WORDS |= {f"{s}{r}x{c}" for s in ("float", "int", "uint", "bool", "half", "double")
               for r in "1234" for c in "1234"}

SLANG_WORDS = set("""
let var import extension associatedtype This property __subscript where is as new func throws some dyn module
implementing __init open public private internal override typealias enum __generic __exported __intrinsic_op
__target_intrinsic __import __include __ref __spirv_version __unsafe each expand functype no_diff fwd_diff bwd_diff
Ref Ptr Optional Tuple none nullptr try catch defer
""".split())

MSL_WORDS = set("""
alignas alignof and and_eq auto bitand bitor catch char char16_t char32_t compl const_cast constexpr decltype
delete dynamic_cast explicit friend goto long mutable noexcept not not_eq operator or or_eq private protected
public reinterpret_cast short signed sizeof static_assert static_cast template this thread_local throw try
typeid typename union using virtual wchar_t xor xor_eq
kernel vertex fragment device constant thread threadgroup threadgroup_imageblock ray_data object_data metal
texture2d texture1d texture3d texturecube depth2d sampler array packed_float2 packed_float3 packed_float4
fract mix dfdx dfdy rint popcount clz ctz as_type fast precise rsqrt select bias level gradient2d stage_in

""".split())

RESERVED_WORDS = frozenset(HLSL_WORDS | SLANG_WORDS | MSL_WORDS)
