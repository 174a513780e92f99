//! The Dockerfile and deploy/kubernetes.yaml checked without a container engine: what a
//! rollout needs from them, against the service's own settings (#18).
#![allow(clippy::unwrap_used)]

use serde_norway::Value;

fn read(path: &str) -> String {
    std::fs::read_to_string(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(path)).unwrap()
}

/// The Dockerfile's instructions, continuation lines joined, comments dropped.
fn instructions() -> Vec<(String, String)> {
    let mut joined = Vec::new();
    let mut current = String::new();
    for line in read("Dockerfile").lines() {
        let line = line.trim();
        if line.starts_with('#') || (line.is_empty() && current.is_empty()) {
            continue;
        }
        match line.strip_suffix('\\') {
            Some(head) => current.push_str(head),
            None => {
                current.push_str(line);
                joined.push(std::mem::take(&mut current));
            }
        }
    }
    joined
        .into_iter()
        .filter(|l| !l.is_empty())
        .map(|l| {
            let (keyword, rest) = l.split_once(' ').unwrap_or((&l, ""));
            (keyword.to_uppercase(), rest.trim().to_owned())
        })
        .collect()
}

fn port(addr: &str) -> &str {
    addr.rsplit(':').next().unwrap()
}

#[test]
fn the_dockerfile_pins_its_images_caches_dependencies_and_checks_its_own_port() {
    let steps = instructions();
    for (keyword, image) in steps.iter().filter(|s| s.0 == "FROM") {
        let image = image.split_whitespace().next().unwrap();
        let tag = image.split_once(':').map(|t| t.1).unwrap_or("");
        assert!(
            !tag.is_empty() && tag != "latest" && !tag.starts_with("1-"),
            "{keyword} {image}: pin a version"
        );
    }
    // The builder's Rust is at least the crate's rust-version.
    let manifest = read("Cargo.toml");
    let minimum = manifest
        .lines()
        .find_map(|l| l.strip_prefix("rust-version = "))
        .unwrap()
        .trim_matches('"');
    let builder = &steps.iter().find(|s| s.0 == "FROM").unwrap().1;
    assert!(builder.starts_with(&format!("rust:{minimum}")), "{builder}");
    // Dependencies cached between builds: the build runs with the registry and target caches.
    let build = steps
        .iter()
        .find(|s| s.0 == "RUN" && s.1.contains("cargo build"))
        .unwrap();
    for cache in ["target=/usr/local/cargo/registry", "target=/src/target"] {
        assert!(
            build.1.contains(&format!("--mount=type=cache,{cache}")),
            "{cache}"
        );
    }
    assert!(build.1.contains("--locked"));
    // Every COPY source from the context exists.
    for (_, args) in steps
        .iter()
        .filter(|s| s.0 == "COPY" && !s.1.starts_with("--from"))
    {
        let parts: Vec<&str> = args.split_whitespace().collect();
        for source in &parts[..parts.len() - 1] {
            assert!(
                std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
                    .join(source)
                    .exists(),
                "COPY {source}: not in the repository"
            );
        }
    }
    // The service listens on THRUSTLINE_ADDR (no --addr to override it), which EXPOSE names,
    // and the health check reads the port it actually listens on from THRUSTLINE_PORT_FILE.
    let env = &steps.iter().find(|s| s.0 == "ENV").unwrap().1;
    let addr = env
        .split_whitespace()
        .find_map(|kv| kv.strip_prefix("THRUSTLINE_ADDR="))
        .unwrap();
    assert_eq!(
        steps.iter().find(|s| s.0 == "EXPOSE").unwrap().1,
        port(addr)
    );
    let cmd = &steps.iter().find(|s| s.0 == "CMD").unwrap().1;
    assert!(
        !cmd.contains("--addr"),
        "CMD {cmd} overrides THRUSTLINE_ADDR"
    );
    let health = &steps.iter().find(|s| s.0 == "HEALTHCHECK").unwrap().1;
    assert!(
        health.contains("$(cat \"$THRUSTLINE_PORT_FILE\")/healthz"),
        "{health}"
    );
    assert!(env.contains("THRUSTLINE_PORT_FILE="), "{env}");
    assert!(
        !health.contains(&format!(":{}/", port(addr))),
        "port hard-coded"
    );
    // Not root.
    let user = &steps.iter().rfind(|s| s.0 == "USER").unwrap().1;
    assert_ne!(user, "root");
    assert_ne!(user, "0");
}

fn env(container: &Value, name: &str) -> Option<f64> {
    container["env"]
        .as_sequence()?
        .iter()
        .find(|e| e["name"] == name)?["value"]
        .as_str()?
        .parse()
        .ok()
}

#[test]
fn the_kubernetes_deployment_rolls_without_dropping_requests_and_runs_restricted() {
    let text = read("deploy/kubernetes.yaml");
    let documents: Vec<Value> = serde_norway::Deserializer::from_str(&text)
        .map(|d| serde::Deserialize::deserialize(d).unwrap())
        .collect();
    let deployment = documents
        .iter()
        .find(|d| d["kind"] == "Deployment")
        .unwrap();
    let service = documents.iter().find(|d| d["kind"] == "Service").unwrap();
    let pod = &deployment["spec"]["template"]["spec"];
    let container = &pod["containers"][0];
    // The image: the crate's version, pulled when missing (not `latest`, pulled every start).
    let version = read("Cargo.toml")
        .lines()
        .find_map(|l| l.strip_prefix("version = "))
        .unwrap()
        .trim_matches('"')
        .to_owned();
    assert_eq!(container["image"], format!("thrustline:{version}").as_str());
    assert_eq!(container["imagePullPolicy"], "IfNotPresent");
    // Pod security "restricted": non-root, seccomp RuntimeDefault, no escalation, no
    // capabilities.
    assert_eq!(pod["securityContext"]["runAsNonRoot"], true);
    assert_eq!(
        pod["securityContext"]["seccompProfile"]["type"],
        "RuntimeDefault"
    );
    let security = &container["securityContext"];
    assert_eq!(security["allowPrivilegeEscalation"], false);
    assert_eq!(security["capabilities"]["drop"][0], "ALL");
    // Rolling updates: a preStop pause, then a drain at least as long as a request can wait
    // (the pool deadline: twice the solve timeout plus 1 s), all within the grace period.
    let pause: f64 = container["lifecycle"]["preStop"]["exec"]["command"][1]
        .as_str()
        .unwrap()
        .parse()
        .unwrap();
    let timeout = env(container, "THRUSTLINE_SOLVE_TIMEOUT_SECS").unwrap_or(30.0);
    let drain = env(container, "THRUSTLINE_DRAIN_SECS").unwrap_or(10.0);
    assert!(
        drain >= 2.0 * timeout + 1.0,
        "drain {drain} s < the longest wait"
    );
    // A batch ends within the drain (its default, 600 s, would not).
    let batch = env(container, "THRUSTLINE_BATCH_TIMEOUT_SECS").unwrap_or(600.0);
    assert!(batch <= drain, "batch {batch} s > drain {drain} s");
    let grace = pod["terminationGracePeriodSeconds"].as_f64().unwrap();
    assert!(
        grace > pause + drain,
        "grace {grace} s ≤ preStop {pause} + drain {drain}"
    );
    // The port: the one --addr names, the probes' and the Service's target.
    let args: Vec<&str> = container["args"]
        .as_sequence()
        .unwrap()
        .iter()
        .map(|a| a.as_str().unwrap())
        .collect();
    let addr = args[args.iter().position(|a| *a == "--addr").unwrap() + 1];
    let http = &container["ports"][0];
    assert_eq!(
        http["containerPort"].as_u64().unwrap().to_string(),
        port(addr)
    );
    for probe in ["readinessProbe", "livenessProbe"] {
        assert_eq!(container[probe]["httpGet"]["path"], "/healthz");
        assert_eq!(container[probe]["httpGet"]["port"], http["name"]);
    }
    assert_eq!(service["spec"]["ports"][0]["targetPort"], http["name"]);
    // Scraping by annotation cannot send a token.
    let scraped =
        deployment["spec"]["template"]["metadata"]["annotations"]["prometheus.io/scrape"] == "true";
    assert!(
        container["env"]
            .as_sequence()
            .unwrap()
            .iter()
            .all(|e| e["name"] != "THRUSTLINE_TOKEN")
            || !scraped
    );
}

#[test]
fn the_autoscaler_owns_the_replica_count_and_scales_on_cpu() {
    let text = read("deploy/kubernetes.yaml");
    let documents: Vec<Value> = serde_norway::Deserializer::from_str(&text)
        .map(|d| serde::Deserialize::deserialize(d).unwrap())
        .collect();
    let deployment = documents
        .iter()
        .find(|d| d["kind"] == "Deployment")
        .unwrap();
    let hpa = documents
        .iter()
        .find(|d| d["kind"] == "HorizontalPodAutoscaler")
        .expect("a HorizontalPodAutoscaler");
    assert_eq!(hpa["apiVersion"], "autoscaling/v2");
    // It scales this Deployment, which leaves the count to it.
    let target = &hpa["spec"]["scaleTargetRef"];
    assert_eq!(target["kind"], "Deployment");
    assert_eq!(target["name"], deployment["metadata"]["name"]);
    assert!(deployment["spec"].get("replicas").is_none());
    // At least two replicas (one can restart while another serves), a bounded maximum.
    let min = hpa["spec"]["minReplicas"].as_u64().unwrap();
    let max = hpa["spec"]["maxReplicas"].as_u64().unwrap();
    assert!(2 <= min && min <= max, "{min}..{max}");
    // On CPU utilisation, which is a share of the request: the container must request CPU.
    let metric = &hpa["spec"]["metrics"][0];
    assert_eq!(metric["resource"]["name"], "cpu");
    let utilisation = metric["resource"]["target"]["averageUtilization"]
        .as_u64()
        .unwrap();
    assert!((1..=100).contains(&utilisation), "{utilisation}");
    let container = &deployment["spec"]["template"]["spec"]["containers"][0];
    assert!(container["resources"]["requests"]["cpu"].as_str().is_some());
}
