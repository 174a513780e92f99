"""schemathesis hooks for .ci/run: how to write and read NDJSON (POST /batch).

A generated batch body (one BatchLine, or whatever negative data the fuzzer makes) is sent as
one JSON line; an answer is read as its first line, which is validated against BatchAnswer.
"""
import json

import schemathesis


@schemathesis.serializer("application/x-ndjson")
def ndjson_serializer(ctx, value):
    return (json.dumps(value) + "\n").encode()


@schemathesis.deserializer("application/x-ndjson")
def ndjson_deserializer(ctx, response):
    # Lines end in "\n" only: splitlines() would also cut at U+0085 and U+2028 inside strings.
    lines = [line for line in response.content.decode().split("\n") if line.strip()]
    if not lines:
        raise ValueError("an NDJSON answer with no line")
    return json.loads(lines[0])
