//! The `thrustline` binary: `thrustline serve [--addr HOST:PORT]` runs the service,
//! `thrustline openapi` prints the OpenAPI document, `thrustline --version` its version.

use std::net::SocketAddr;
use std::process::ExitCode;

use thrustline::Settings;

const USAGE: &str =
    "usage: thrustline serve [--addr HOST:PORT]   run the service (default 127.0.0.1:8080)
       thrustline openapi                    print the OpenAPI document
       thrustline --version                  print the version

Environment (read by `serve`):
  THRUSTLINE_ADDR                 listen address (default 127.0.0.1:8080; --addr wins)
  THRUSTLINE_MAX_RUNNING          solves running at once (default: the CPU count)
  THRUSTLINE_MAX_QUEUED           solves waiting for a worker before 503 (default 64)
  THRUSTLINE_BODY_LIMIT           largest request body in bytes (default 4194304)
  THRUSTLINE_SOLVE_TIMEOUT_SECS   time limit of a whole solve in seconds, up to 86400 (default 30)
  THRUSTLINE_BATCH_TIMEOUT_SECS   time limit of a whole POST /batch in seconds, up to 86400 (default 600)
  THRUSTLINE_DRAIN_SECS           after SIGTERM, time open connections get, 0..3600 (default 10)
  THRUSTLINE_HEADER_TIMEOUT_SECS  time to send a request head (and idle keep-alive), default 10
  THRUSTLINE_BODY_TIMEOUT_SECS    time to send a request body, 0.1..3600 (default 30)
  THRUSTLINE_MAX_CONNECTIONS      open connections at most (default 1024)
  THRUSTLINE_SOLVE_MEMORY_MIB     memory the heavy solves may take together, 16..1048576 (default 384)
  THRUSTLINE_TOKEN                bearer token required by every route but /healthz (default none;
                                  set but empty refuses to start)
  THRUSTLINE_CORS_ORIGINS         comma-separated origins allowed by CORS, or * (default none)
  THRUSTLINE_PORT_FILE            a file to write the port actually listened on to, once listening
                                  (the container's health check reads it; default none)
  RUST_LOG                        log filter (default info)";

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(String::as_str) {
        Some("openapi") => {
            print!("{}", thrustline::openapi::openapi_json());
            ExitCode::SUCCESS
        }
        // `serve --help` is a question, not a mistake.
        Some("serve") if args[1..].iter().any(|a| a == "-h" || a == "--help") => {
            println!("{USAGE}");
            ExitCode::SUCCESS
        }
        Some("serve") => match parse_serve(&args[1..]) {
            Ok(settings) => run(settings),
            Err(message) => {
                eprintln!("{message}\n\n{USAGE}");
                ExitCode::from(2)
            }
        },
        Some("-h" | "--help" | "help") => {
            println!("{USAGE}");
            ExitCode::SUCCESS
        }
        Some("-V" | "--version" | "version") => {
            println!("thrustline {}", env!("CARGO_PKG_VERSION"));
            ExitCode::SUCCESS
        }
        _ => {
            eprintln!("{USAGE}");
            ExitCode::from(2)
        }
    }
}

fn parse_serve(args: &[String]) -> Result<Settings, String> {
    let mut settings = Settings::from_env()?;
    let mut rest = args.iter();
    while let Some(arg) = rest.next() {
        let value = match arg.split_once('=') {
            Some(("--addr", value)) => value.to_owned(),
            _ if arg == "--addr" => rest.next().ok_or("--addr needs HOST:PORT")?.clone(),
            _ => return Err(format!("unknown argument {arg:?}")),
        };
        settings.addr = value
            .parse::<SocketAddr>()
            .map_err(|_| format!("--addr {value:?} is not HOST:PORT"))?;
    }
    Ok(settings)
}

fn run(settings: Settings) -> ExitCode {
    use std::io::IsTerminal;
    tracing_subscriber::fmt()
        // Colour codes only for a person at a terminal, not in log files and collectors.
        .with_ansi(std::io::stdout().is_terminal())
        .with_env_filter(
            tracing_subscriber::EnvFilter::try_from_default_env()
                .unwrap_or_else(|_| tracing_subscriber::EnvFilter::new("info")),
        )
        .init();
    let runtime = match tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .build()
    {
        Ok(runtime) => runtime,
        Err(error) => {
            eprintln!("cannot start the runtime: {error}");
            return ExitCode::FAILURE;
        }
    };
    let code = runtime.block_on(async move {
        let listener = match tokio::net::TcpListener::bind(settings.addr).await {
            Ok(listener) => listener,
            Err(error) => {
                eprintln!("cannot listen on {}: {error}", settings.addr);
                return ExitCode::FAILURE;
            }
        };
        tracing::info!(addr = %settings.addr, "thrustline listening");
        // The port actually listened on (an --addr given, or port 0), for health checks.
        if let Some(path) = std::env::var_os("THRUSTLINE_PORT_FILE") {
            let port = listener.local_addr().map(|a| a.port());
            match port.and_then(|port| std::fs::write(&path, port.to_string())) {
                Ok(()) => {}
                Err(error) => tracing::warn!(%error, "cannot write THRUSTLINE_PORT_FILE"),
            }
        }
        match thrustline::serve(listener, settings, shutdown_signal()).await {
            Ok(()) => ExitCode::SUCCESS,
            Err(error) => {
                eprintln!("server error: {error}");
                ExitCode::FAILURE
            }
        }
    });
    // The drain is over: requests still open are dropped (which cancels their solves' budgets)
    // and the process exits now. Dropping the runtime would wait for every solve still running
    // on the blocking pool to notice (regression: 16 s and more after SIGTERM with a 2 s drain).
    runtime.shutdown_timeout(std::time::Duration::ZERO);
    code
}

/// Completes on Ctrl-C or SIGTERM.
async fn shutdown_signal() {
    let ctrl_c = async {
        let _ = tokio::signal::ctrl_c().await;
    };
    #[cfg(unix)]
    let terminate = async {
        match tokio::signal::unix::signal(tokio::signal::unix::SignalKind::terminate()) {
            Ok(mut signal) => {
                signal.recv().await;
            }
            Err(_) => std::future::pending::<()>().await,
        }
    };
    #[cfg(not(unix))]
    let terminate = std::future::pending::<()>();
    tokio::select! {
        () = ctrl_c => {},
        () = terminate => {},
    }
    tracing::info!("shutting down: finishing in-flight requests");
}
