"""The front end: .mxm text (mxm.lark) -> Spec, frozen dataclasses with source positions."""
