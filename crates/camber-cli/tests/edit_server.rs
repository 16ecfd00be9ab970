//! `camber edit` over a real socket: the binary is started on a free port, a small HTTP/1.1
//! client on `TcpStream` fetches the page and drives a drag over one kept-alive connection,
//! requests from other sites are refused, and the process is killed at the end.

#![allow(clippy::unwrap_used)] // helpers outside #[test] fns unwrap like the tests do

use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use serde_json::Value;

/// The editor process, killed when dropped (also when a test fails).
struct Editor {
    child: Child,
    addr: String,
}

impl Drop for Editor {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// Starts `camber edit` on a copy of the bundled blade section, port 0, and reads the address
/// from its first line.
fn start(dir: &Path) -> Editor {
    let file = dir.join("blade.json");
    std::fs::copy(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/sketches/blade_section.json"),
        &file,
    )
    .unwrap();
    let mut child = Command::new(assert_cmd::cargo::cargo_bin("camber"))
        .arg("edit")
        .arg(&file)
        // As the file has it: the drag below moves the whole unsolved blade, so that each answer
        // is over a kilobyte.
        .args(["--port", "0", "--no-solve"])
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let mut line = String::new();
    BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut line)
        .unwrap();
    let mut editor = Editor {
        child,
        addr: String::new(),
    };
    // "camber edit: FILE at http://127.0.0.1:PORT/ (Ctrl-C to stop)"
    let url = line
        .split_whitespace()
        .find(|w| w.starts_with("http://"))
        .unwrap_or_else(|| panic!("no address in {line:?}"));
    editor.addr = url
        .trim_start_matches("http://")
        .trim_end_matches('/')
        .to_owned();
    assert!(editor.addr.starts_with("127.0.0.1:"), "{line}");
    editor
}

/// One answer: status, headers (lower-case names), body.
struct Answer {
    status: u16,
    headers: Vec<(String, String)>,
    body: String,
}

impl Answer {
    fn header(&self, name: &str) -> Option<&str> {
        self.headers
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, v)| v.as_str())
    }

    fn json(&self) -> Value {
        serde_json::from_str(&self.body).unwrap()
    }
}

/// Sends one request on a kept-alive connection and reads the answer by its Content-Length.
fn request(
    stream: &mut BufReader<TcpStream>,
    method: &str,
    path: &str,
    extra: &[(&str, &str)],
    body: &str,
) -> Answer {
    let mut head = format!(
        "{method} {path} HTTP/1.1\r\nHost: {}\r\nContent-Length: {}\r\n",
        stream.get_ref().peer_addr().unwrap(),
        body.len()
    );
    for (k, v) in extra {
        head.push_str(&format!("{k}: {v}\r\n"));
    }
    head.push_str("\r\n");
    head.push_str(body);
    stream.get_mut().write_all(head.as_bytes()).unwrap();
    let mut status_line = String::new();
    stream.read_line(&mut status_line).unwrap();
    let status = status_line
        .split_whitespace()
        .nth(1)
        .unwrap()
        .parse()
        .unwrap();
    let mut headers = Vec::new();
    loop {
        let mut line = String::new();
        stream.read_line(&mut line).unwrap();
        let line = line.trim_end();
        if line.is_empty() {
            break;
        }
        let (k, v) = line.split_once(':').unwrap();
        headers.push((k.trim().to_ascii_lowercase(), v.trim().to_owned()));
    }
    let len: usize = headers
        .iter()
        .find(|(k, _)| k == "content-length")
        .map_or(0, |(_, v)| v.parse().unwrap());
    let mut body = vec![0; len];
    stream.read_exact(&mut body).unwrap();
    Answer {
        status,
        headers,
        body: String::from_utf8(body).unwrap(),
    }
}

fn connect(editor: &Editor) -> BufReader<TcpStream> {
    let stream = TcpStream::connect(&editor.addr).unwrap();
    stream
        .set_read_timeout(Some(Duration::from_secs(20)))
        .unwrap();
    BufReader::new(stream)
}

const JSON: (&str, &str) = ("Content-Type", "application/json");

#[test]
fn the_editor_serves_its_page_and_a_drag_over_http() {
    let dir = tempfile::tempdir().unwrap();
    let editor = start(dir.path());
    let mut c = connect(&editor);

    let page = request(&mut c, "GET", "/", &[], "");
    assert_eq!(page.status, 200);
    assert!(page
        .header("content-type")
        .unwrap()
        .starts_with("text/html"));
    assert!(page.body.contains("<title>camber edit</title>"));
    let state = request(&mut c, "GET", "/api/state", &[], "");
    assert_eq!(state.status, 200);
    assert_eq!(state.header("cache-control"), Some("no-store"));
    assert_eq!(
        state.json()["scene"]["entities"].as_array().unwrap().len(),
        4
    );

    let start = request(
        &mut c,
        "POST",
        "/api/drag/start",
        &[JSON],
        r#"{"entity": 1, "index": 2}"#,
    );
    assert_eq!(start.status, 200, "{}", start.body);
    // Twenty updates on one connection. Each answer is over a kilobyte, which tiny_http writes
    // in two parts: without TCP_NODELAY the second waited for a delayed acknowledgement
    // (about 40 ms on Linux) every time.
    let mut times = Vec::new();
    for k in 0..20 {
        let body = format!(r#"{{"to": [-0.01, {}]}}"#, -0.01 + 0.0005 * f64::from(k));
        let t = Instant::now();
        let moved = request(&mut c, "POST", "/api/drag/move", &[JSON], &body);
        times.push(t.elapsed());
        assert_eq!(moved.status, 200, "{}", moved.body);
        assert!(moved.body.len() > 1024);
        let moved = moved.json();
        let ids: Vec<u64> = moved["entities"]
            .as_array()
            .unwrap()
            .iter()
            .map(|e| e["id"].as_u64().unwrap())
            .collect();
        assert!(ids.contains(&1), "{ids:?}");
    }
    times.sort();
    if cfg!(target_os = "linux") {
        assert!(times[10] < Duration::from_millis(30), "{times:?}");
    }
    let end = request(&mut c, "POST", "/api/drag/end", &[JSON], "{}");
    assert_eq!(end.status, 200, "{}", end.body);
    assert_eq!(end.json()["unsaved"], true);
    let save = request(&mut c, "POST", "/api/save", &[JSON], "{}");
    assert_eq!(save.status, 200, "{}", save.body);
    let saved = std::fs::read_to_string(dir.path().join("blade.json")).unwrap();
    let reloaded = camber_sketch::file::from_json(&saved).unwrap();
    let p = reloaded
        .point(camber_sketch::PointRef::Control(
            camber_sketch::EntityId(1),
            2,
        ))
        .unwrap();
    assert!((p.x + 0.01).abs() < 1e-12 && (p.y - (-0.01 + 0.0005 * 19.0)).abs() < 1e-12);
}

#[test]
fn requests_from_other_sites_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let editor = start(dir.path());
    let mut c = connect(&editor);
    let origin = format!("http://{}", editor.addr);
    let cases: [(&[(&str, &str)], u16); 4] = [
        (&[("Origin", "https://example.com"), JSON], 403),
        (&[("Content-Type", "text/plain")], 415),
        (&[("Origin", &origin), JSON], 200),
        (&[JSON], 200),
    ];
    for (headers, status) in cases {
        let answer = request(&mut c, "POST", "/api/drag/cancel", headers, "{}");
        // 409 (no drag in progress) means the request got through to the handler.
        let got = if answer.status == 409 {
            200
        } else {
            answer.status
        };
        assert_eq!(got, status, "{headers:?}: {}", answer.body);
        assert!(answer.json()["error"].is_string() || status == 200);
    }
    // A page under another name (DNS rebinding) cannot even read.
    let mut raw = TcpStream::connect(&editor.addr).unwrap();
    raw.write_all(b"GET /api/state HTTP/1.1\r\nHost: evil.example:80\r\nConnection: close\r\n\r\n")
        .unwrap();
    let mut text = String::new();
    raw.read_to_string(&mut text).unwrap();
    assert!(text.starts_with("HTTP/1.1 403"), "{text}");
    assert!(text.contains("is not localhost or an IP address"));
}
