//! The editor's HTTP server: a thin loop over `tiny_http` that reads each request, refuses the
//! ones that do not come from a page of this server, and hands the rest to
//! [`EditorState::handle`]. Requests are answered one at a time, in order, so a drag's moves
//! reach the session in the order the page sent them.
//!
//! The server listens on the loopback interface by default. Because any web page in the same
//! browser could send requests to it, [`guard`] refuses:
//! - a `Host` that is neither `localhost` nor an IP address (a DNS-rebinding page reaches the
//!   server under its own domain name);
//! - a state-changing request whose `Origin` is another site;
//! - a `POST` whose body is not declared `application/json` (a cross-site form cannot send
//!   that without the browser asking first, and this server never says yes).

use std::io::Read as _;
use std::net::{IpAddr, SocketAddr};

use anyhow::{anyhow, Result};

use super::{EditorState, Response};

/// The largest request body read, in bytes (a drag move is about 40).
pub const MAX_BODY: usize = 1 << 20;

/// The request headers [`guard`] looks at.
#[derive(Debug, Clone, Copy, Default)]
pub struct Head<'a> {
    /// The method (`GET`, `POST`, …).
    pub method: &'a str,
    /// The `Host` header, if any.
    pub host: Option<&'a str>,
    /// The `Origin` header, if any.
    pub origin: Option<&'a str>,
    /// The `Content-Type` header, if any.
    pub content_type: Option<&'a str>,
}

/// The refusal of a request that may come from another site, or `None` to let it through.
///
/// ```
/// use camber_cli::editor::server::{guard, Head};
/// let page = Head { method: "POST", host: Some("127.0.0.1:8080"),
///                   origin: Some("http://127.0.0.1:8080"), content_type: Some("application/json") };
/// assert!(guard(&page).is_none());
/// let other = Head { origin: Some("https://example.com"), ..page };
/// assert_eq!(guard(&other).map(|r| r.status), Some(403));
/// ```
pub fn guard(head: &Head) -> Option<Response> {
    if let Some(host) = head.host {
        if !is_local_host(host) {
            return Some(Response::error(
                403,
                &format!("refused: Host {host:?} is not localhost or an IP address"),
            ));
        }
    }
    let reads_only = matches!(head.method, "GET" | "HEAD");
    if !reads_only {
        if let Some(origin) = head.origin {
            let same = head
                .host
                .is_some_and(|h| origin.eq_ignore_ascii_case(&format!("http://{h}")));
            if !same {
                return Some(Response::error(
                    403,
                    &format!("refused: a request from {origin} (another site)"),
                ));
            }
        }
    }
    if head.method == "POST" {
        let json = head.content_type.is_some_and(|c| {
            c.split(';')
                .next()
                .is_some_and(|t| t.trim().eq_ignore_ascii_case("application/json"))
        });
        if !json {
            return Some(Response::error(
                415,
                "POST bodies must be sent as Content-Type: application/json",
            ));
        }
    }
    None
}

/// Whether a `Host` header names this machine by address or as `localhost` (any port).
fn is_local_host(host: &str) -> bool {
    let name = if let Some(rest) = host.strip_prefix('[') {
        // [v6]:port
        rest.split(']').next().unwrap_or_default()
    } else {
        match host.rsplit_once(':') {
            Some((name, port)) if port.chars().all(|c| c.is_ascii_digit()) => name,
            _ => host,
        }
    };
    name.eq_ignore_ascii_case("localhost") || name.parse::<IpAddr>().is_ok()
}

/// A listening editor server.
pub struct Server {
    http: tiny_http::Server,
    addr: SocketAddr,
}

impl std::fmt::Debug for Server {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Server").field("addr", &self.addr).finish()
    }
}

impl Server {
    /// Listens on `addr` (port 0: a free port the system picks).
    ///
    /// The listening socket gets `TCP_NODELAY`, which the accepted connections inherit (on
    /// Linux and the BSDs): tiny_http writes the headers and a body of more than a kilobyte in
    /// two writes, and with Nagle's algorithm on, the body then waits for the browser's delayed
    /// acknowledgement of the headers, about 40 ms per drag update.
    ///
    /// # Errors
    /// The address is taken or not this machine's.
    pub fn bind(addr: SocketAddr) -> Result<Self> {
        let failed = |e: &dyn std::fmt::Display| anyhow!("cannot listen on {addr}: {e}");
        let listener = std::net::TcpListener::bind(addr).map_err(|e| failed(&e))?;
        socket2::SockRef::from(&listener)
            .set_tcp_nodelay(true)
            .map_err(|e| failed(&e))?;
        let http = tiny_http::Server::from_listener(listener, None).map_err(|e| failed(&e))?;
        let addr = http
            .server_addr()
            .to_ip()
            .ok_or_else(|| anyhow!("cannot listen on {addr}: not an IP socket"))?;
        Ok(Self { http, addr })
    }

    /// The address it listens on (with the port the system picked).
    pub fn addr(&self) -> SocketAddr {
        self.addr
    }

    /// The editor's address for a browser, `http://127.0.0.1:PORT/`.
    pub fn url(&self) -> String {
        format!("http://{}/", self.addr)
    }

    /// Answers requests until the process ends.
    ///
    /// # Errors
    /// The listening socket fails.
    pub fn serve(&self, state: &mut EditorState) -> Result<()> {
        loop {
            let request = self
                .http
                .recv()
                .map_err(|e| anyhow!("{}: the server stopped: {e}", self.addr))?;
            answer(request, state);
        }
    }
}

/// Reads one request, guards it, handles it, writes the answer. A client that went away is
/// not an error of the server.
fn answer(mut request: tiny_http::Request, state: &mut EditorState) {
    let method = request.method().as_str().to_owned();
    let url = request.url().to_owned();
    let header = |name: &'static str| {
        request
            .headers()
            .iter()
            .find(|h| h.field.equiv(name))
            .map(|h| h.value.as_str().to_owned())
    };
    let (host, origin, content_type) = (header("Host"), header("Origin"), header("Content-Type"));
    let head = Head {
        method: &method,
        host: host.as_deref(),
        origin: origin.as_deref(),
        content_type: content_type.as_deref(),
    };
    let response = match guard(&head) {
        Some(refused) => refused,
        None => {
            let mut body = Vec::new();
            let read = request
                .as_reader()
                .take(MAX_BODY as u64 + 1)
                .read_to_end(&mut body);
            match read {
                Err(e) => Response::error(400, &format!("cannot read the request body: {e}")),
                Ok(n) if n > MAX_BODY => Response::error(413, "the request body is too large"),
                Ok(_) => state.handle(&method, &url, &body),
            }
        }
    };
    let mut out = tiny_http::Response::from_data(response.body).with_status_code(response.status);
    for (field, value) in [
        ("Content-Type", response.content_type),
        ("Cache-Control", "no-store"),
        ("X-Content-Type-Options", "nosniff"),
    ] {
        if let Ok(h) = tiny_http::Header::from_bytes(field.as_bytes(), value.as_bytes()) {
            out.add_header(h);
        }
    }
    let _ = request.respond(out);
}

#[cfg(test)]
mod tests {
    use super::*;

    fn post(host: &str, origin: Option<&'static str>, ct: Option<&'static str>) -> Option<u16> {
        let head = Head {
            method: "POST",
            host: Some(host),
            origin,
            content_type: ct,
        };
        guard(&head).map(|r| r.status)
    }

    #[test]
    fn local_hosts_pass_and_names_do_not() {
        for host in [
            "127.0.0.1:80",
            "localhost:1234",
            "[::1]:99",
            "localhost",
            "10.0.0.2",
        ] {
            assert!(is_local_host(host), "{host}");
        }
        for host in ["evil.example:80", "example.com", "127.0.0.1.nip.io:80"] {
            assert!(!is_local_host(host), "{host}");
        }
        let get = Head {
            method: "GET",
            host: Some("evil.example:8080"),
            ..Head::default()
        };
        assert_eq!(guard(&get).map(|r| r.status), Some(403));
    }

    #[test]
    fn posts_need_json_and_the_same_origin() {
        let json = Some("application/json; charset=utf-8");
        assert_eq!(post("127.0.0.1:5", Some("http://127.0.0.1:5"), json), None);
        assert_eq!(post("127.0.0.1:5", None, json), None);
        assert_eq!(
            post("127.0.0.1:5", Some("http://127.0.0.1:6"), json),
            Some(403)
        );
        assert_eq!(post("127.0.0.1:5", Some("null"), json), Some(403));
        assert_eq!(post("127.0.0.1:5", None, Some("text/plain")), Some(415));
        assert_eq!(post("127.0.0.1:5", None, None), Some(415));
        // Reading is allowed from anywhere on this machine: the browser keeps other sites
        // from seeing the answer.
        let get = Head {
            method: "GET",
            host: Some("127.0.0.1:5"),
            origin: Some("https://example.com"),
            content_type: None,
        };
        assert!(guard(&get).is_none());
    }
}
