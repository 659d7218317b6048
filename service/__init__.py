"""ShaderX HTTP service: FastAPI app, shared graph-hash cache and render-worker pools."""
