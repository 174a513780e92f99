# Multi-stage build of the thrustline service.
# Build: docker build -t thrustline .    Run: docker run -p 8080:8080 thrustline
FROM rust:1-bookworm AS build
WORKDIR /src
COPY Cargo.toml Cargo.lock clippy.toml ./
COPY crates ./crates
COPY src ./src
COPY openapi ./openapi
RUN cargo build --release --locked --bin thrustline

FROM debian:bookworm-slim
RUN apt-get update \
    && apt-get install -y --no-install-recommends curl ca-certificates \
    && rm -rf /var/lib/apt/lists/* \
    && useradd --system --uid 10001 --no-create-home thrustline
COPY --from=build /src/target/release/thrustline /usr/local/bin/thrustline
USER thrustline
ENV THRUSTLINE_ADDR=0.0.0.0:8080 RUST_LOG=info
EXPOSE 8080
HEALTHCHECK --interval=10s --timeout=3s --start-period=5s --retries=3 \
    CMD curl -fsS http://127.0.0.1:8080/healthz || exit 1
ENTRYPOINT ["thrustline"]
CMD ["serve", "--addr", "0.0.0.0:8080"]
