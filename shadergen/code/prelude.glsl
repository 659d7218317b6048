// The closure, shader and light types every library source may use (code/library.py parses this
// before the libraries). An EDF is the radiance it emits; a material is a surface shader.

struct surfaceshader { vec3 color; vec3 transparency; };
struct volumeshader { vec3 color; vec3 transparency; };
struct displacementshader { vec3 offset; float scale; };
struct lightshader { vec3 intensity; vec3 direction; };
struct BSDF { vec3 response; vec3 throughput; };
#define EDF vec3
struct VDF { vec3 response; vec3 throughput; };
#define material surfaceshader
#define MAX_LIGHT_SOURCES 3
struct LightData { int type; vec3 position; vec3 direction; vec3 color; float intensity; float decay_rate; float inner_angle; float outer_angle; };
