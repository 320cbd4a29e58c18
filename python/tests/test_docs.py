"""Every public function, class member and property of the module has a docstring (units and shapes live there)."""
import inspect

import hooke


def undocumented():
    missing = []
    for name in dir(hooke):
        obj = getattr(hooke, name)
        if name.startswith("_") or inspect.ismodule(obj) or (isinstance(obj, type) and issubclass(obj, BaseException)):
            continue
        if isinstance(obj, type):
            for member, value in vars(obj).items():
                if member.startswith("_"):
                    continue
                doc = (value.__doc__ if isinstance(value, property) else getattr(value, "__doc__", "")) or ""
                if not doc.strip() or doc.strip().startswith("(self"):
                    missing.append(f"{name}.{member}")
        elif callable(obj):
            doc = (obj.__doc__ or "").strip()
            if not doc or (doc.startswith(name + "(") and "\n" not in doc):  # only pybind11's signature line
                missing.append(name)
    return missing


def test_every_public_name_has_a_docstring():
    assert undocumented() == []
    assert "N/m" in hooke.calibrate.__doc__ and "Pa" in hooke.Material.__init__.__doc__
