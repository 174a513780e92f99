# syntax=docker/dockerfile:1
# Multi-stage build of the thrustline service (BuildKit, the default builder since Docker 23).
# Build: docker build -t thrustline:0.1.0 .    Run: docker run -p 8080:8080 thrustline:0.1.0
# The port is THRUSTLINE_ADDR's: `docker run -e THRUSTLINE_ADDR=0.0.0.0:9000 -p 9000:9000 …`
# moves the service and its health check together.

# The toolchain is pinned (the locked dependencies need Rust ≥ 1.89, Cargo.toml's rust-version).
FROM rust:1.89-bookworm AS build
WORKDIR /src
COPY Cargo.toml Cargo.lock clippy.toml ./
COPY crates ./crates
COPY src ./src
COPY openapi ./openapi
# The registry and the target directory live in BuildKit caches: a change under src/ recompiles
# this crate, not the ~200 dependencies. The binary is copied out of the cache to the layer.
RUN --mount=type=cache,target=/usr/local/cargo/registry \
    --mount=type=cache,target=/src/target \
    cargo build --release --locked --bin thrustline \
    && cp target/release/thrustline /usr/local/bin/thrustline

FROM debian:bookworm-slim
RUN apt-get update \
    && apt-get install -y --no-install-recommends curl ca-certificates \
    && rm -rf /var/lib/apt/lists/* \
    && useradd --system --uid 10001 --no-create-home thrustline
COPY --from=build /usr/local/bin/thrustline /usr/local/bin/thrustline
USER 10001
ENV THRUSTLINE_ADDR=0.0.0.0:8080 THRUSTLINE_PORT_FILE=/tmp/thrustline.port RUST_LOG=info
EXPOSE 8080
# The port checked is the one the service actually listens on, which it writes to
# THRUSTLINE_PORT_FILE (`serve --addr 0.0.0.0:9000` included).
HEALTHCHECK --interval=10s --timeout=3s --start-period=5s --retries=3 \
    CMD curl -fsS "http://127.0.0.1:$(cat "$THRUSTLINE_PORT_FILE")/healthz" || exit 1
ENTRYPOINT ["thrustline"]
CMD ["serve"]
