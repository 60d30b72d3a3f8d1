"""Settings: the base of every config section's settings, a frozen dataclass that is the one
place where the section's defaults are written (a paper's value where the paper gives one).

A rule script builds it from its config section (``Ma2010Settings.from_dict(config["ma2010"])``)
and passes it whole to the library; ``config/schema.yaml`` repeats the defaults for the
reader and ``tests/core/test_settings.py`` holds the two equal. Subsections are nested settings
classes; list-valued keys are tuples (frozen) and come back as lists from :meth:`to_dict`.
"""

from __future__ import annotations

import dataclasses
import types
import typing
from collections.abc import Mapping
from typing import Any, ClassVar, TypeVar

S = TypeVar("S", bound="Settings")


class Settings:
    """Mixin of a frozen dataclass holding one config section (or subsection).

    ``SECTION``: the section's dotted config key, for messages (e.g. ``"ma2010"``).
    ``RENAMED``: former keys of this section -> their new names; such a key in a config
    raises an error that names the new key.
    """

    SECTION: ClassVar[str] = ""
    RENAMED: ClassVar[dict[str, str]] = {}

    @classmethod
    def from_dict(cls: type[S], values: Mapping[str, Any] | None, where: str | None = None) -> S:
        """The settings from a config mapping (missing keys take their defaults). An unknown or
        renamed key raises ValueError naming it as a dotted config key under ``where``."""
        where = where or cls.SECTION or cls.__name__
        values = dict(values or {})
        renamed = sorted(set(values) & set(cls.RENAMED))
        if renamed:
            raise ValueError("; ".join(f"config key {where}.{k} is now {where}.{cls.RENAMED[k]}" for k in renamed))
        hints = typing.get_type_hints(cls)
        known = [f.name for f in dataclasses.fields(cls)]
        unknown = sorted(set(values) - set(known))
        if unknown:
            raise ValueError(
                f"unknown config key(s) {', '.join(f'{where}.{k}' for k in unknown)} "
                f"(allowed here: {', '.join(sorted(known))})"
            )
        kwargs = {k: _coerce(hints[k], v, f"{where}.{k}") for k, v in values.items()}
        try:
            return cls(**kwargs)
        except (TypeError, ValueError) as exc:
            raise ValueError(f"config section {where}: {exc}") from None

    @classmethod
    def renamed_keys(cls, prefix: str = "") -> dict[str, str]:
        """Every former key of this section and its subsections (``RENAMED``) -> its name now, both
        as dotted config keys under ``prefix`` (the section's own key by default)."""
        prefix = prefix or cls.SECTION
        out = {f"{prefix}.{old}": f"{prefix}.{new}" for old, new in cls.RENAMED.items()}
        for name, hint in typing.get_type_hints(cls).items():
            sub = _settings_class(hint)
            if sub is not None:
                out.update(sub.renamed_keys(f"{prefix}.{name}"))
        return out

    def to_dict(self) -> dict[str, Any]:
        """The settings as a config mapping (nested dicts, lists for tuples)."""
        return {f.name: _plain(getattr(self, f.name)) for f in dataclasses.fields(self)}

    def replace(self: S, **changes: Any) -> S:
        """A copy with ``changes`` (dataclasses.replace); ``sub__key=value`` changes ``key`` of
        subsection ``sub``, as scikit-learn's ``set_params`` names a nested parameter."""
        nested: dict[str, dict[str, Any]] = {}
        for name in [k for k in changes if "__" in k]:
            sub, key = name.split("__", 1)
            nested.setdefault(sub, {})[key] = changes.pop(name)
        for sub, inner in nested.items():
            changes[sub] = changes.get(sub, getattr(self, sub)).replace(**inner)
        return dataclasses.replace(self, **changes)


def _settings_class(hint: Any) -> type[Settings] | None:
    """The Settings class of a field's type hint (``Sub`` or ``Sub | None``), else None."""
    if isinstance(hint, type) and issubclass(hint, Settings):
        return hint
    if typing.get_origin(hint) in (typing.Union, types.UnionType):
        subs = [a for a in typing.get_args(hint) if isinstance(a, type) and issubclass(a, Settings)]
        return subs[0] if len(subs) == 1 else None
    return None


def _is_tuple(hint: Any) -> bool:
    if typing.get_origin(hint) is tuple or hint is tuple:
        return True
    if typing.get_origin(hint) in (typing.Union, types.UnionType):
        return any(_is_tuple(a) for a in typing.get_args(hint))
    return False


def _coerce(hint: Any, value: Any, where: str) -> Any:
    """A config value as the field's type: a mapping into its Settings class, a list into a
    tuple (nested lists into nested tuples) where the field is a tuple."""
    sub = _settings_class(hint)
    if sub is not None and isinstance(value, Mapping):
        return sub.from_dict(value, where)
    if _is_tuple(hint) and isinstance(value, list):
        return _frozen(value)
    return value


def _frozen(value: Any) -> Any:
    return tuple(_frozen(v) for v in value) if isinstance(value, (list, tuple)) else value


def _plain(value: Any) -> Any:
    if isinstance(value, Settings):
        return value.to_dict()
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if isinstance(value, Mapping):
        return {k: _plain(v) for k, v in value.items()}
    return value
