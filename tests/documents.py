"""Small documents several test folders read."""


def image_document(file: str, filtertype: str = "linear", type: str = "color3") -> str:
    """An <image> of `type` reading `file` with `filtertype`, and an output of it."""
    return f"""<?xml version="1.0"?>
<materialx version="1.39">
  <image name="img" type="{type}"><input name="file" type="filename" value="{file}"/>
    <input name="filtertype" type="string" value="{filtertype}"/></image>
  <output name="out" type="{type}" nodename="img"/>
</materialx>"""
