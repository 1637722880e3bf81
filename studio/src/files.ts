// The workspace's files over plain HTTP (POST /api/CALL with a JSON body).

// The server's refusal: its sentence, and the HTTP status (404: no such file, 403: a path
// refused, 422: not a valid feel/1 file; docs/studio.md).
export class ApiError extends Error {
  constructor(
    message: string,
    readonly status: number,
  ) {
    super(message);
  }
}

export async function api<T = Record<string, unknown>>(call: string, body: object): Promise<T> {
  const res = await fetch(`/api/${call}`, {
    method: 'POST',
    headers: { 'Content-Type': 'application/json' },
    body: JSON.stringify(body),
  });
  const data = (await res.json()) as T & { error?: string };
  if (!res.ok) throw new ApiError(data.error ?? `${call} failed (${res.status})`, res.status);
  return data;
}
