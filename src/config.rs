//! Service settings, read once at start-up from flags and `THRUSTLINE_*` environment variables
//! and passed down; there is no global configuration.

use std::net::SocketAddr;
use std::time::Duration;

/// Settings of a running service.
#[derive(Debug, Clone)]
pub struct Settings {
    /// Address to listen on. Defaults to 127.0.0.1:8080 (`THRUSTLINE_ADDR`).
    pub addr: SocketAddr,
    /// Solves running at once. Defaults to the number of CPUs (`THRUSTLINE_MAX_RUNNING`).
    pub max_running: usize,
    /// Solves allowed to wait for a worker before requests get 503. Defaults to 64
    /// (`THRUSTLINE_MAX_QUEUED`).
    pub max_queued: usize,
    /// Largest request body in bytes. Defaults to 4 MiB (`THRUSTLINE_BODY_LIMIT`).
    pub body_limit: usize,
    /// Time a request may wait for its solve before a 503. Defaults to 30 s
    /// (`THRUSTLINE_SOLVE_TIMEOUT_SECS`).
    pub solve_timeout: Duration,
    /// Time limit of a whole `POST /batch`, from when its body is read: lines not answered by
    /// then are answered 503 `over_time_limit` (each line also has the solve time limit).
    /// Defaults to 600 s (`THRUSTLINE_BATCH_TIMEOUT_SECS`, 0 < s ≤ 86400).
    pub batch_timeout: Duration,
    /// Bearer token required by every endpoint but /healthz; none by default
    /// (`THRUSTLINE_TOKEN`).
    pub token: Option<String>,
    /// Origins allowed by CORS, for dashboards in browsers; none by default, which sends no
    /// CORS headers (`THRUSTLINE_CORS_ORIGINS`, comma-separated, or `*`).
    pub cors_origins: Vec<String>,
    /// How long open connections may finish after a shutdown signal before the process stops.
    /// Defaults to 10 s (`THRUSTLINE_DRAIN_SECS`, 0 to 3600).
    pub drain_timeout: Duration,
    /// Time a client has to send a request's head once its connection is ready for one (idle
    /// keep-alive connections close after it too). Defaults to 10 s
    /// (`THRUSTLINE_HEADER_TIMEOUT_SECS`, 0.1 to 3600).
    pub header_timeout: Duration,
    /// Time a client has to send a request's body. Defaults to 30 s
    /// (`THRUSTLINE_BODY_TIMEOUT_SECS`, 0.1 to 3600).
    pub body_timeout: Duration,
    /// Open connections at most; more are closed on accept. Defaults to 1024
    /// (`THRUSTLINE_MAX_CONNECTIONS`).
    pub max_connections: usize,
    /// Mebibytes the heavy solves running at once may take together; one solve that would
    /// take more is refused (422). Defaults to 384 (`THRUSTLINE_SOLVE_MEMORY_MIB`, 16 to
    /// 1048576).
    pub solve_memory_mib: u32,
}

impl Default for Settings {
    fn default() -> Self {
        Self {
            addr: SocketAddr::from(([127, 0, 0, 1], 8080)),
            max_running: std::thread::available_parallelism().map_or(2, |n| n.get()),
            max_queued: 64,
            body_limit: 4 * 1024 * 1024,
            solve_timeout: Duration::from_secs(30),
            batch_timeout: Duration::from_secs(600),
            token: None,
            cors_origins: Vec::new(),
            drain_timeout: Duration::from_secs(10),
            header_timeout: Duration::from_secs(10),
            body_timeout: Duration::from_secs(30),
            max_connections: 1024,
            solve_memory_mib: 384,
        }
    }
}

impl Settings {
    /// Defaults overridden by the `THRUSTLINE_*` environment variables that are set.
    pub fn from_env() -> Result<Self, String> {
        let mut settings = Self::default();
        if let Some(addr) = read("THRUSTLINE_ADDR")? {
            settings.addr = addr;
        }
        if let Some(n) = read::<usize>("THRUSTLINE_MAX_RUNNING")? {
            settings.max_running = n.max(1);
        }
        if let Some(n) = read("THRUSTLINE_MAX_QUEUED")? {
            settings.max_queued = n;
        }
        if let Some(n) = read("THRUSTLINE_BODY_LIMIT")? {
            settings.body_limit = n;
        }
        settings.read_timeouts()?;
        if let Some(n) = read::<usize>("THRUSTLINE_MAX_CONNECTIONS")? {
            settings.max_connections = n.max(1);
        }
        if let Some(mib) = read::<u32>("THRUSTLINE_SOLVE_MEMORY_MIB")? {
            if !(16..=1 << 20).contains(&mib) {
                return Err("THRUSTLINE_SOLVE_MEMORY_MIB must be 16 to 1048576".to_owned());
            }
            settings.solve_memory_mib = mib;
        }
        settings.read_access()?;
        Ok(settings)
    }

    /// Overrides the solve, batch, drain, header and body timeouts from the environment.
    fn read_timeouts(&mut self) -> Result<(), String> {
        for (name, target) in [
            ("THRUSTLINE_SOLVE_TIMEOUT_SECS", &mut self.solve_timeout),
            ("THRUSTLINE_BATCH_TIMEOUT_SECS", &mut self.batch_timeout),
        ] {
            if let Some(seconds) = read::<f64>(name)? {
                if !(seconds.is_finite() && seconds > 0.0 && seconds <= 86_400.0) {
                    return Err(format!("{name} must be a number of seconds, 0 < s ≤ 86400"));
                }
                *target = Duration::from_secs_f64(seconds);
            }
        }
        if let Some(seconds) = read::<f64>("THRUSTLINE_DRAIN_SECS")? {
            if !(seconds.is_finite() && (0.0..=3600.0).contains(&seconds)) {
                return Err(
                    "THRUSTLINE_DRAIN_SECS must be a number of seconds, 0 ≤ s ≤ 3600".to_owned(),
                );
            }
            self.drain_timeout = Duration::from_secs_f64(seconds);
        }
        for (name, target) in [
            ("THRUSTLINE_HEADER_TIMEOUT_SECS", &mut self.header_timeout),
            ("THRUSTLINE_BODY_TIMEOUT_SECS", &mut self.body_timeout),
        ] {
            if let Some(seconds) = read::<f64>(name)? {
                if !(seconds.is_finite() && (0.1..=3600.0).contains(&seconds)) {
                    return Err(format!(
                        "{name} must be a number of seconds, 0.1 ≤ s ≤ 3600"
                    ));
                }
                *target = Duration::from_secs_f64(seconds);
            }
        }
        Ok(())
    }

    /// Overrides the bearer token and the CORS origins from the environment.
    fn read_access(&mut self) -> Result<(), String> {
        if let Ok(token) = std::env::var("THRUSTLINE_TOKEN") {
            // An empty token is a mistake, not "no authentication": refuse to start.
            if token.trim().is_empty() {
                return Err(
                    "THRUSTLINE_TOKEN is set but empty: unset it to run without authentication, \
                     or give a token"
                        .to_owned(),
                );
            }
            self.token = Some(token);
        }
        if let Ok(origins) = std::env::var("THRUSTLINE_CORS_ORIGINS") {
            self.cors_origins = origins
                .split(',')
                .map(|o| o.trim().to_owned())
                .filter(|o| !o.is_empty())
                .collect();
        }
        Ok(())
    }
}

/// The environment variable `name` parsed, if it is set.
fn read<T: std::str::FromStr>(name: &str) -> Result<Option<T>, String> {
    match std::env::var(name) {
        Ok(text) => text
            .parse()
            .map(Some)
            .map_err(|_| format!("{name}={text:?} is not valid")),
        Err(_) => Ok(None),
    }
}
