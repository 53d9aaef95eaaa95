"""Draft 2020-12 schema checks fast enough for every vector and every answer.

`osdkc vectors check` validates about 35,000 vector cases and `osdkc run`
every response of a testee. The pure-Python `jsonschema` needs about 1.7 ms
per vector case (a minute for the whole suite); the compiled `jsonschema_rs`
needs a hundredth of that. So the compiled validator answers the common
question, "is this valid?", and `jsonschema` stays the authority for
everything else: an instance the compiled one rejects, or cannot take at
all, is validated again by `jsonschema`, whose errors (and so every message
the kit prints) are what they always were, and which may still find it
valid (its regular expressions are Python's, for one). The only trust placed
in the compiled validator is that what it accepts is valid; it passes the
JSON-Schema-Test-Suite, and tests/test_schema_check.py holds it to
`jsonschema` on every vector and on broken ones.
"""
from __future__ import annotations

import functools
from typing import Any, Iterator, Sequence


class SchemaCheck:
    """A validator of one schema with jsonschema's `iter_errors` and
    `is_valid`, given the (uri, contents) of the schemas it refers to."""

    def __init__(self, schema: dict, resources: Sequence[tuple[str, dict]] = ()) -> None:
        import jsonschema_rs

        self.schema, self.resources = schema, list(resources)
        fast_registry = jsonschema_rs.Registry(self.resources, draft=jsonschema_rs.Draft202012) \
            if self.resources else None
        try:
            self.fast = jsonschema_rs.Draft202012Validator(schema, registry=fast_registry) if fast_registry \
                else jsonschema_rs.Draft202012Validator(schema)
        except ValueError:
            self.fast = None  # a schema only jsonschema takes: it answers every question

    def schema_problem(self) -> str | None:
        """Why the schema is not a valid draft 2020-12 schema (jsonschema's
        message), or None when it is. The compiled validator checked it
        against the metaschema as it compiled it, in a fraction of the time
        jsonschema's own check takes (a third of a second for
        spec/rules.schema.json, paid by every process that loads the rules);
        only a schema it refused goes to jsonschema, whose message is the one
        reported."""
        if self.fast is not None:
            return None
        from jsonschema import Draft202012Validator
        from jsonschema.exceptions import SchemaError

        try:
            Draft202012Validator.check_schema(self.schema)
        except SchemaError as exc:
            return exc.message
        return None

    @functools.cached_property
    def authority(self) -> Any:
        # built on first need: importing jsonschema alone costs a tenth of a
        # second, in every process that loads the rules, which are valid
        from jsonschema import Draft202012Validator
        from referencing import Registry, Resource
        from referencing.jsonschema import DRAFT202012

        registry = Registry().with_resources(
            (uri, Resource.from_contents(doc, default_specification=DRAFT202012)) for uri, doc in self.resources)
        return Draft202012Validator(self.schema, registry=registry)

    def _surely_valid(self, instance: Any) -> bool:
        if self.fast is None:
            return False
        try:
            return self.fast.is_valid(instance)
        except (ValueError, TypeError, OverflowError, RecursionError):
            return False  # not a JSON value it can take (a float NaN, a huge int): ask the authority

    def is_valid(self, instance: Any) -> bool:
        return self._surely_valid(instance) or self.authority.is_valid(instance)

    def iter_errors(self, instance: Any) -> Iterator[Any]:
        if self._surely_valid(instance):
            return iter(())
        return self.authority.iter_errors(instance)
