"""The built-in colour management system: the library's transform nodes
(`ND_<source>_to_<working>_<type>`, libraries/cmlib), a simplified set of common spaces. A pair it
has no node for is left as it is, with a warning (MaterialX's default system does the same)."""

# Names MaterialX's default colour management accepts for the spaces of its transforms.
COLORSPACE_ALIASES = {"gamma18": "g18_rec709", "gamma22": "g22_rec709", "gamma24": "rec709_display",
                      "lin_rec709_scene": "lin_rec709", "lin_ap1": "acescg", "lin_ap1_scene": "acescg",
                      "none": "raw"}


class BuiltinCMS:
    name = "builtin"
    identity = None  # the default: records made before systems existed keep their keys

    def resolve(self, space: str | None) -> str | None:
        return COLORSPACE_ALIASES.get(space, space)

    def transform(self, builder, name: str, source: str | None, working: str | None, type_name: str, where: str):
        """The library's transform node from `source` to `working`, or None (no transform needed,
        or none in the library)."""
        working, source = self.resolve(working), self.resolve(source)
        if not working or not source or source in (working, "raw") or type_name not in ("color3", "color4"):
            return None
        return builder.transform_node(name, f"ND_{source}_to_{working}_{type_name}", where)
