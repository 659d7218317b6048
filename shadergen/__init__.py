"""ShaderX service core: MaterialX documents to shader source and variable listings."""

__version__ = "0.1.0"
