// A live WebGL2 preview of an `essl` record, drawn as the service's thumbnails are: the same
// sphere, camera, environment maps and uniforms (all fetched from /v1/preview), file textures
// bound as the renderer binds them (textures.js), then composited over the same grey and
// sRGB-encoded. Programs are kept by their source, so a record whose source did not change is
// drawn without compiling; a uniform change is one gl.uniform call.

import { previewArray, previewScene } from "./api.js";
import { applySampling, constantTexture, floatTexture, toRgba } from "./gltextures.js";
import { sceneOverrides } from "./sceneuniforms.js";
import { defaultColour, samplingOf, TextureLoader, textureRequests } from "./textures.js";

const MAX_PROGRAMS = 16;
const COMPILE_POLL_MS = 20;

const POST_VERTEX = `#version 300 es
void main() {
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}`;
// what the thumbnails' PNG encoder does: premultiplied linear colour over a linear grey, then sRGB
const POST_PIXEL = `#version 300 es
precision highp float;
uniform sampler2D u_image;
uniform float u_background;
out vec4 colour;
void main() {
  vec4 c = texelFetch(u_image, ivec2(gl_FragCoord.xy), 0);
  if (any(isnan(c)) || any(isinf(c))) c = vec4(0.0);
  vec3 linear = max(c.rgb + u_background * (1.0 - clamp(c.a, 0.0, 1.0)), 0.0);
  vec3 srgb = mix(linear * 12.92, 1.055 * pow(linear, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, linear));
  colour = vec4(clamp(srgb, 0.0, 1.0), 1.0);
}`;

export class Preview {
  // `files`: the files dropped on the page (files.js), which textures are looked up in first
  static async create(canvas, files) {
    const gl = canvas.getContext("webgl2", { antialias: false, preserveDrawingBuffer: true });
    if (!gl) return null;
    const scene = await previewScene();
    if (scene.error) throw new Error(`preview scene: ${scene.error.message}`);
    const names = [...Object.keys(scene.mesh.streams), ...Object.keys(scene.environment)];
    const arrays = Object.fromEntries(await Promise.all(names.map(async (name) => [name, await previewArray(name)])));
    arrays.indices = await previewArray("indices", Uint32Array);
    return new Preview(gl, scene, arrays, await link(gl, POST_VERTEX, POST_PIXEL), files);
  }

  constructor(gl, scene, arrays, post, files) {
    this.gl = gl;
    this.scene = scene;
    this.stats = { compiles: 0, draws: 0 };
    this.programs = new Map();  // vertex + pixel source -> { program, vao, uniforms, units }
    this.current = null;
    this.values = new Map();    // uniform name -> the record's (or the user's) value
    // the thumbnails' sphere and environment, kept to go back to after another choice
    this.sphere = { name: scene.mesh.name, components: scene.mesh.streams, indices: arrays.indices,
                    streams: Object.fromEntries(Object.keys(scene.mesh.streams).map((name) => [name, arrays[name]])) };
    this.useMesh(this.sphere);
    this.skies = {};
    for (const [name, image] of Object.entries(scene.environment)) {
      this.skies[name] = environmentTexture(gl, arrays[name], image);
    }
    this.environment = this.skies;
    this.choices = { intensity: 1, rotationDegrees: 0, turntableDegrees: 0, radianceMips: null };
    this.overrides = sceneOverrides(scene.uniforms, this.choices);
    this.turning = false;
    this.black = constantTexture(gl, [0, 0, 0, 1]);
    this.textures = new TextureLoader(gl, files);
    this.files = new Map();     // sampler name -> { request, texture, problem } of the record shown
    this.target = renderTarget(gl, gl.drawingBufferWidth, gl.drawingBufferHeight);
    this.post = { program: post, image: gl.getUniformLocation(post, "u_image"),
                  background: gl.getUniformLocation(post, "u_background") };
    this.postVao = gl.createVertexArray();
    this.pending = false;
    this.frameWaiters = [];
  }

  buffer(kind, data) {
    const buffer = this.gl.createBuffer();
    this.gl.bindBuffer(kind, buffer);
    this.gl.bufferData(kind, data, this.gl.STATIC_DRAW);
    return buffer;
  }

  // Show a record: compile only when its source is new, then bind all its values. Rejects with
  // an Error whose message is the driver's log when the source does not compile or link.
  // The record's file textures are loaded meanwhile, so its first frame has them.
  async show(record) {
    const vertex = record.stages.vertex, pixel = record.stages.pixel;
    const key = vertex + "\u0000" + pixel;
    const files = this.loadTextures(record);
    let entry = this.programs.get(key);
    if (!entry) {
      entry = this.prepare(await link(this.gl, vertex, pixel));
      this.stats.compiles += 1;
      this.programs.set(key, entry);
      if (this.programs.size > MAX_PROGRAMS) this.release(this.programs.keys().next().value);
    }
    this.files = await files;
    this.current = entry;
    this.values = new Map();
    for (const stage of Object.values(record.blocks)) {
      for (const variable of [...(stage.PublicUniforms ?? []), ...(stage.PrivateUniforms ?? [])]) {
        if (variable.value !== null && variable.value !== undefined) this.values.set(variable.name, variable.value);
      }
    }
    this.gl.useProgram(entry.program);
    for (const name of entry.uniforms.keys()) this.apply(name);
    this.requestDraw();
  }

  async loadTextures(record) {
    const requests = textureRequests(record);
    const loaded = await Promise.all(requests.map((request) => this.textures.load(request.file)));
    return new Map(requests.map((request, i) => [request.name, { request, ...loaded[i] }]));
  }

  // Why file textures of the record shown are drawn in their default colour: [text]
  textureProblems() {
    return [...this.files.values()].map((file) => file.problem).filter(Boolean);
  }

  // Files dropped: textures are looked up again, the record redrawn with what they give.
  async reloadTextures(record) {
    this.files = await this.loadTextures(record);
    this.requestDraw();
  }

  // One uniform changed by the user: written on the GPU, drawn on the next frame.
  setUniform(name, value) {
    this.values.set(name, value);
    if (!this.current || !this.current.uniforms.has(name)) return false;
    this.gl.useProgram(this.current.program);
    this.apply(name);
    this.requestDraw();
    return true;
  }

  apply(name) {
    const { location, type } = this.current.uniforms.get(name);
    const fixed = this.overrides[name] ?? this.scene.uniforms[name];
    const value = fixed ?? this.values.get(name);
    if (value === undefined || value === null) return;
    setUniform(this.gl, location, type, flatten(value));
  }

  prepare(program) {
    const gl = this.gl;
    const uniforms = new Map();
    const units = [];
    for (let i = 0; i < gl.getProgramParameter(program, gl.ACTIVE_UNIFORMS); i++) {
      const info = gl.getActiveUniform(program, i);
      const name = info.name.replace(/\[0\]$/, "");
      const location = gl.getUniformLocation(program, info.name);
      if (info.type === gl.SAMPLER_2D) units.push({ location, name });
      else uniforms.set(name, { location, type: info.type });
    }
    return { program, vao: this.vertexArray(program), uniforms, units };
  }

  // The program's vertex inputs bound to the mesh's streams.
  vertexArray(program) {
    const gl = this.gl;
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    for (let i = 0; i < gl.getProgramParameter(program, gl.ACTIVE_ATTRIBUTES); i++) {
      const info = gl.getActiveAttrib(program, i);
      const location = gl.getAttribLocation(program, info.name);
      const stream = this.streams[info.name] ?? this.fallbackStream(info.name);
      if (stream) {
        gl.bindBuffer(gl.ARRAY_BUFFER, stream.buffer);
        gl.enableVertexAttribArray(location);
        gl.vertexAttribPointer(location, stream.components, gl.FLOAT, false, 0, 0);
      } else {
        // streams a mesh never has take MaterialX's defaults: white colours, zero otherwise
        gl.disableVertexAttribArray(location);
        const white = info.name.startsWith("i_color_") ? 1 : 0;
        gl.vertexAttrib4f(location, white, white, white, 1);
      }
    }
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, this.indexBuffer);
    gl.bindVertexArray(null);
    return vao;
  }

  // Scene choices: a mesh (meshes.js, or null for the sphere) -- every program's vertex arrays
  // are bound to it again.
  useMesh(mesh) {
    const gl = this.gl;
    mesh ??= this.sphere;
    for (const stream of Object.values(this.streams ?? {})) gl.deleteBuffer(stream.buffer);
    if (this.indexBuffer) gl.deleteBuffer(this.indexBuffer);
    this.streams = {};
    for (const [name, data] of Object.entries(mesh.streams)) {
      this.streams[name] = { buffer: this.buffer(gl.ARRAY_BUFFER, data), components: mesh.components[name] };
    }
    this.indexBuffer = this.buffer(gl.ELEMENT_ARRAY_BUFFER, mesh.indices);
    this.indexCount = mesh.indices.length;
    this.mesh = mesh.name;
    for (const entry of this.programs?.values() ?? []) {
      gl.deleteVertexArray(entry.vao);
      entry.vao = this.vertexArray(entry.program);
    }
    this.requestDraw?.();
  }

  // An environment ({ radiance, irradiance } decoded images; null for the thumbnails' sky).
  useEnvironment(maps) {
    const gl = this.gl;
    for (const texture of this.environment === this.skies ? [] : Object.values(this.environment)) gl.deleteTexture(texture);
    if (!maps) {
      this.environment = this.skies;
      this.choose({ radianceMips: null });
      return;
    }
    this.environment = {
      u_envRadiance: environmentTexture(gl, maps.radiance.data, maps.radiance),
      u_envIrradiance: environmentTexture(gl, maps.irradiance.data, maps.irradiance),
    };
    this.choose({ radianceMips: Math.floor(Math.log2(Math.max(maps.radiance.width, maps.radiance.height))) + 1 });
  }

  // Intensity, rotation (degrees), turntable (on or off): the scene's uniforms over the thumbnails'.
  choose(choices) {
    const { turntable, ...values } = choices;
    Object.assign(this.choices, values);
    if (turntable !== undefined) this.turn(turntable);
    this.overrides = sceneOverrides(this.scene.uniforms, this.choices);
    if (this.current) {
      this.gl.useProgram(this.current.program);
      // every scene uniform: one an earlier choice overrode is the thumbnails' again when unset
      for (const name of new Set([...Object.keys(this.overrides), ...Object.keys(this.scene.uniforms)])) {
        if (this.current.uniforms.has(name)) this.apply(name);
      }
    }
    this.requestDraw();
  }

  // The turntable: a quarter turn every few seconds, drawn every frame while on.
  turn(on) {
    this.turning = on;
    if (!on) return this.choose({ turntableDegrees: 0 });
    const step = () => {
      if (!this.turning) return;
      this.choose({ turntableDegrees: (performance.now() / 1000 * 30) % 360 });
      requestAnimationFrame(step);
    };
    requestAnimationFrame(step);
  }

  fallbackStream(name) {
    return /^i_texcoord_\d+$/.test(name) ? this.streams.i_texcoord_0 : null;
  }

  release(key) {
    const entry = this.programs.get(key);
    this.gl.deleteVertexArray(entry.vao);
    this.gl.deleteProgram(entry.program);
    this.programs.delete(key);
  }

  requestDraw() {
    if (this.pending) return;
    this.pending = true;
    requestAnimationFrame(() => {
      this.pending = false;
      this.draw();
    });
  }

  // An environment map as it was made; a file texture with its node's sampling now (a control
  // may have changed it), or its default colour; black for a sampler the record does not list.
  bindSampler(name) {
    const gl = this.gl;
    if (this.environment[name]) return gl.bindTexture(gl.TEXTURE_2D, this.environment[name]);
    const file = this.files.get(name);
    if (!file) return gl.bindTexture(gl.TEXTURE_2D, this.black);
    gl.bindTexture(gl.TEXTURE_2D, file.texture ?? this.textures.constant(defaultColour(file.request, this.values)));
    applySampling(gl, samplingOf(file.request, this.values));
  }

  draw() {
    const gl = this.gl, entry = this.current;
    if (!entry) return;
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.target.framebuffer);
    gl.viewport(0, 0, this.target.width, this.target.height);
    gl.clearColor(0, 0, 0, 0);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.enable(gl.DEPTH_TEST);
    gl.useProgram(entry.program);
    entry.units.forEach(({ location, name }, unit) => {
      gl.activeTexture(gl.TEXTURE0 + unit);
      this.bindSampler(name);
      gl.uniform1i(location, unit);
    });
    gl.bindVertexArray(entry.vao);
    gl.drawElements(gl.TRIANGLES, this.indexCount, gl.UNSIGNED_INT, 0);

    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.viewport(0, 0, gl.drawingBufferWidth, gl.drawingBufferHeight);
    gl.disable(gl.DEPTH_TEST);
    gl.useProgram(this.post.program);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, this.target.colour);
    gl.uniform1i(this.post.image, 0);
    gl.uniform1f(this.post.background, this.scene.background);
    gl.bindVertexArray(this.postVao);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.bindVertexArray(null);
    this.stats.draws += 1;
    this.frameWaiters.splice(0).forEach((resolve) => resolve());
  }

  // Resolves once the next frame is drawn: how the page times an edit to its frame.
  nextFrame() {
    return new Promise((resolve) => this.frameWaiters.push(resolve));
  }
}

// Compile and link; with KHR_parallel_shader_compile the wait happens between frames, so the page
// stays responsive while a large shader compiles (a thousand lines take seconds on a software GPU).
async function link(gl, vertexSource, pixelSource) {
  const program = gl.createProgram();
  const stages = [[gl.VERTEX_SHADER, vertexSource, "vertex"], [gl.FRAGMENT_SHADER, pixelSource, "pixel"]];
  const shaders = stages.map(([kind, source, stage]) => {
    const shader = gl.createShader(kind);
    gl.shaderSource(shader, source);
    gl.compileShader(shader);
    gl.attachShader(program, shader);
    return { shader, stage };
  });
  gl.linkProgram(program);
  const parallel = gl.getExtension("KHR_parallel_shader_compile");
  while (parallel && !gl.getProgramParameter(program, parallel.COMPLETION_STATUS_KHR)) {
    await new Promise((resolve) => setTimeout(resolve, COMPILE_POLL_MS));
  }
  let failure = null;
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) {
    const broken = shaders.find(({ shader }) => !gl.getShaderParameter(shader, gl.COMPILE_STATUS));
    failure = broken ? `the ${broken.stage} stage does not compile in WebGL2:\n${gl.getShaderInfoLog(broken.shader)}`
                     : `the stages do not link in WebGL2:\n${gl.getProgramInfoLog(program)}`;
  }
  shaders.forEach(({ shader }) => gl.deleteShader(shader));
  if (failure) {
    gl.deleteProgram(program);
    throw new Error(failure);
  }
  return program;
}

function flatten(value) {
  if (Array.isArray(value)) return value.flatMap(flatten);
  if (typeof value === "boolean") return [value ? 1 : 0];
  return [Number(value)];
}

function setUniform(gl, location, type, v) {
  switch (type) {
    case gl.FLOAT: return gl.uniform1fv(location, v);
    case gl.FLOAT_VEC2: return gl.uniform2fv(location, v);
    case gl.FLOAT_VEC3: return gl.uniform3fv(location, v);
    case gl.FLOAT_VEC4: return gl.uniform4fv(location, v);
    case gl.INT: case gl.BOOL: return gl.uniform1iv(location, v.map(Math.round));
    case gl.INT_VEC2: case gl.BOOL_VEC2: return gl.uniform2iv(location, v.map(Math.round));
    case gl.INT_VEC3: case gl.BOOL_VEC3: return gl.uniform3iv(location, v.map(Math.round));
    case gl.INT_VEC4: case gl.BOOL_VEC4: return gl.uniform4iv(location, v.map(Math.round));
    // matrices arrive in GLSL's column-major storage order (the generated code's convention)
    case gl.FLOAT_MAT3: return gl.uniformMatrix3fv(location, false, v);
    case gl.FLOAT_MAT4: return gl.uniformMatrix4fv(location, false, v);
    default: return undefined;
  }
}

// A lat-long map with its mip chain: longitude wraps, latitude stops at the poles.
function environmentTexture(gl, rgb, { width, height, channels }) {
  const texture = floatTexture(gl, toRgba(rgb, channels), width, height);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR_MIPMAP_LINEAR);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.REPEAT);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
  return texture;
}

// Linear colour is drawn into a float target when the browser can render to one (as the
// thumbnails' float framebuffer), else into 8 bits.
function renderTarget(gl, width, height) {
  const float = gl.getExtension("EXT_color_buffer_float") !== null;
  const colour = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, colour);
  gl.texStorage2D(gl.TEXTURE_2D, 1, float ? gl.RGBA16F : gl.RGBA8, width, height);
  const depth = gl.createRenderbuffer();
  gl.bindRenderbuffer(gl.RENDERBUFFER, depth);
  gl.renderbufferStorage(gl.RENDERBUFFER, gl.DEPTH_COMPONENT24, width, height);
  const framebuffer = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, colour, 0);
  gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.RENDERBUFFER, depth);
  gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  return { framebuffer, colour, width, height };
}
